// vigil's relative threshold detector (detector.type relative_threshold; not the paper's rule, which is
// threshold_detector.h), streaming with zero latency.
//
// Per axis (wx, wy, wz, ax, ay, az), the reference is the mean of the axis' last n = reference_samples normal
// values: a per-axis bound on the deviation from a short causal local level, which follows the robot's motion
// (gravity and slow accelerations) while a glitch stands out against it. A value with
// |value - reference| > bounds[axis] is abnormal and is truncated to reference +- bound (mitigation truncate)
// or replaced by the reference itself (mitigation mean). Abnormal values never enter the
// reference. After max_run consecutive abnormal values the axis accepts the new level: its reference restarts
// from the current value (so a real step in the motion, e.g. hitting an obstacle, cannot lock the axis out).
// The first value of each axis starts the reference and is always normal.
//
// Calibration from clean data: CalibrateRelativeThresholdBounds() runs the same reference over a glitch-free
// stream and returns, per axis, calibration_margin x the largest |value - reference| seen.
#pragma once

#include <array>
#include <vector>

#include "detectors/detector.h"
#include "detectors/running_mean.h"

namespace vigil::detectors {

class RelativeThresholdDetector final : public Detector {
 public:
  // InputError when bounds does not have 6 positive entries.
  explicit RelativeThresholdDetector(const RelativeThresholdOptions& options);

  void Push(const ImuSample& raw, std::vector<DetectedSample>* out) override;
  void Finish(std::vector<DetectedSample>*) override {}
  int latency_samples() const override { return 0; }

 private:
  // The running reference of one axis: a ring of the last n normal values.
  struct AxisState {
    RunningMean reference;  // the last reference_samples normal values
    int run = 0;            // consecutive abnormal values
    void Accept(double value) { reference.Add(value), run = 0; }
    void Restart(double value) { reference.Clear(), Accept(value); }
  };

  RelativeThresholdOptions options_;
  std::array<AxisState, kNumImuAxes> axes_;
};

// Per-axis bounds calibrated on clean data (see above); `options` supplies reference_samples and the margin.
// InputError when `clean` is empty.
std::vector<double> CalibrateRelativeThresholdBounds(const ImuStream& clean,
                                                     const RelativeThresholdOptions& options);

}  // namespace vigil::detectors
