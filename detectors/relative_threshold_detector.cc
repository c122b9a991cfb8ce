#include "detectors/relative_threshold_detector.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace vigil::detectors {

RelativeThresholdDetector::RelativeThresholdDetector(const RelativeThresholdOptions& options)
    : options_(options) {
  if (options_.bounds.size() != static_cast<std::size_t>(kNumImuAxes))
    throw InputError("detector.relative_threshold.bounds: expected 6 numbers (wx, wy, wz, ax, ay, az), got " +
                     std::to_string(options_.bounds.size()));
  for (double b : options_.bounds)
    if (!(b > 0.0)) throw InputError("detector.relative_threshold.bounds: every bound must be > 0");
  if (options_.reference_samples < 1)
    throw InputError("detector.relative_threshold.reference_samples: must be >= 1");
  if (options_.max_run < 1) throw InputError("detector.relative_threshold.max_run: must be >= 1");
  for (AxisState& axis : axes_) axis.reference = RunningMean(options_.reference_samples);
}

void RelativeThresholdDetector::Push(const ImuSample& raw, std::vector<DetectedSample>* out) {
  DetectedSample result{raw, 0};
  for (int a = 0; a < kNumImuAxes; ++a) {
    AxisState& axis = axes_[a];
    const double value = raw.axis(a);
    if (axis.reference.empty()) {
      axis.Accept(value);
      continue;
    }
    const double reference = axis.reference.Mean();
    const double deviation = value - reference;
    const double bound = options_.bounds[a];
    if (std::abs(deviation) <= bound) {
      axis.Accept(value);
      continue;
    }
    if (++axis.run >= options_.max_run) {  // a persistent new level, not a glitch
      axis.Restart(value);
      continue;
    }
    result.flagged_axes |= static_cast<uint8_t>(1u << a);
    result.sample.axis(a) = options_.mitigation == ThresholdMitigation::kTruncate
                                ? reference + std::copysign(bound, deviation)
                                : reference;
  }
  out->push_back(result);
}

std::vector<double> CalibrateRelativeThresholdBounds(const ImuStream& clean,
                                                     const RelativeThresholdOptions& options) {
  if (clean.empty()) throw InputError("threshold calibration: the clean stream is empty");
  const int n = std::max(1, options.reference_samples);
  std::vector<double> bounds(kNumImuAxes, 0.0);
  for (int a = 0; a < kNumImuAxes; ++a) {
    // The detector's reference with every value normal: the mean of the previous n values.
    double sum = 0.0, largest = 0.0;
    for (std::size_t t = 0; t < clean.size(); ++t) {
      const int have = static_cast<int>(std::min<std::size_t>(t, n));
      if (have > 0) largest = std::max(largest, std::abs(clean[t].axis(a) - sum / have));
      sum += clean[t].axis(a);
      if (t >= static_cast<std::size_t>(n)) sum -= clean[t - n].axis(a);
    }
    bounds[a] = options.calibration_margin * largest;
  }
  // A constant axis (e.g. an ideal IMU at rest) would give a zero bound: keep a tiny positive one.
  for (double& b : bounds) b = std::max(b, 1e-9);
  return bounds;
}

}  // namespace vigil::detectors
