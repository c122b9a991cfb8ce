// The paper's threshold detector ("trunc", detector.type threshold), streaming with zero latency.
//
// The paper "identifies any measurement beyond the specified threshold" and, in its VINS integration,
// "we replace the abnormal values with the threshold". The rule here is that one, per axis (wx, wy, wz, ax,
// ay, az) on the measured value itself: a value v with v > upper[axis] or v < lower[axis] is abnormal (a
// value equal to a bound is normal). Mitigation threshold clamps it to the bound it violated; mitigation mean
// (the paper's other option, "the average of the last n samples") replaces it by the mean of the axis' last
// mean_samples output values, i.e. already mitigated ones, so a burst of glitches does not feed itself (the
// first value of a stream has no history: it is clamped). Unlike vigil's relative threshold
// (relative_threshold_detector.h) nothing follows the motion: the bounds must admit every value of normal
// motion, which is the paper's tuning dilemma (a robot starting to move reads like a glitch).
//
// Calibration from clean data (never the data being cleaned): CalibrateThresholdBounds() takes, per axis, the
// range [min, max] of a glitch-free stream and widens it about its centre by calibration_margin:
// bounds = (max + min) / 2 -+ margin (max - min) / 2. A run with `calibration: clean` calibrates on a
// glitch-free simulation of its scenario with seed DeriveSeed(seed, "calibration"); `vigil templates` prints
// the bounds of a recording as a ready --set.
#pragma once

#include <array>
#include <vector>

#include "detectors/detector.h"
#include "detectors/running_mean.h"

namespace vigil::detectors {

class ThresholdDetector final : public Detector {
 public:
  // Uses options.lower / options.upper whatever options.calibration says (the caller calibrates).
  // InputError unless both have 6 entries with lower <= upper.
  explicit ThresholdDetector(const ThresholdOptions& options);

  void Push(const ImuSample& raw, std::vector<DetectedSample>* out) override;
  void Finish(std::vector<DetectedSample>*) override {}
  int latency_samples() const override { return 0; }

 private:
  // The last mean_samples output values of one axis (mitigation mean).
  ThresholdOptions options_;
  std::array<RunningMean, kNumImuAxes> history_;  // the last mean_samples output values
};

// Per-axis bounds from a clean stream (see above): fills bounds->lower and bounds->upper (6 each) using
// options.calibration_margin. InputError when `clean` is empty.
struct ThresholdBounds {
  std::vector<double> lower, upper;
};
ThresholdBounds CalibrateThresholdBounds(const ImuStream& clean, const ThresholdOptions& options);

// `options` with calibrated bounds and calibration manual (what a run hands to MakeDetector).
ThresholdOptions WithBounds(ThresholdOptions options, const ThresholdBounds& bounds);

}  // namespace vigil::detectors
