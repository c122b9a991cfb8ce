#include "detectors/threshold_detector.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace vigil::detectors {

ThresholdDetector::ThresholdDetector(const ThresholdOptions& options) : options_(options) {
  for (const auto* bounds : {&options_.lower, &options_.upper})
    if (bounds->size() != static_cast<std::size_t>(kNumImuAxes))
      throw InputError(std::string("detector.threshold.") + (bounds == &options_.lower ? "lower" : "upper") +
                       ": expected 6 numbers (wx, wy, wz, ax, ay, az), got " +
                       std::to_string(bounds->size()));
  for (int a = 0; a < kNumImuAxes; ++a)
    if (!(options_.lower[a] <= options_.upper[a]))
      throw InputError("detector.threshold.lower: must be <= detector.threshold.upper on every axis (axis " +
                       std::to_string(a) + ")");
  if (options_.mean_samples < 1) throw InputError("detector.threshold.mean_samples: must be >= 1");
  history_.fill(RunningMean(options_.mean_samples));
}

void ThresholdDetector::Push(const ImuSample& raw, std::vector<DetectedSample>* out) {
  DetectedSample result{raw, 0};
  for (int a = 0; a < kNumImuAxes; ++a) {
    double& value = result.sample.axis(a);
    const double lower = options_.lower[a], upper = options_.upper[a];
    if (value > upper || value < lower) {
      result.flagged_axes |= static_cast<uint8_t>(1u << a);
      const double clamped = value > upper ? upper : lower;
      const RunningMean& h = history_[a];
      value = options_.mitigation == ThresholdMitigation::kMean && !h.empty() ? h.Mean() : clamped;
    }
    history_[a].Add(value);
  }
  out->push_back(result);
}

ThresholdBounds CalibrateThresholdBounds(const ImuStream& clean, const ThresholdOptions& options) {
  if (clean.empty()) throw InputError("threshold calibration: the clean stream is empty");
  ThresholdBounds bounds;
  for (int a = 0; a < kNumImuAxes; ++a) {
    double lo = clean.front().axis(a), hi = lo;
    for (const ImuSample& s : clean) {
      lo = std::min(lo, s.axis(a));
      hi = std::max(hi, s.axis(a));
    }
    const double centre = 0.5 * (hi + lo), half = 0.5 * (hi - lo) * options.calibration_margin;
    bounds.lower.push_back(centre - half);
    bounds.upper.push_back(centre + half);
  }
  return bounds;
}

ThresholdOptions WithBounds(ThresholdOptions options, const ThresholdBounds& bounds) {
  options.lower = bounds.lower;
  options.upper = bounds.upper;
  options.calibration = ThresholdCalibration::kManual;
  return options;
}

}  // namespace vigil::detectors
