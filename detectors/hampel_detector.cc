#include "detectors/hampel_detector.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "detectors/slice_features.h"

namespace vigil::detectors {
namespace {
constexpr double kMadToSigma = 1.4826;
}  // namespace

HampelDetector::HampelDetector(const HampelOptions& options) : options_(options) {
  if (options_.half_window < 1) throw InputError("detector.hampel.half_window: must be >= 1");
  if (!(options_.n_sigma > 0.0)) throw InputError("detector.hampel.n_sigma: must be > 0");
  values_.reserve(2 * options_.half_window + 1);
  deviations_.reserve(2 * options_.half_window + 1);
}

void HampelDetector::Emit(int pos, std::vector<DetectedSample>* out) {
  const int h = options_.half_window;
  const int lo = std::max(0, pos - h), hi = std::min(static_cast<int>(window_.size()) - 1, pos + h);
  const int n = hi - lo + 1;
  DetectedSample result{window_[pos], 0};
  for (int a = 0; a < kNumImuAxes; ++a) {
    values_.resize(n);
    for (int i = 0; i < n; ++i) values_[i] = window_[lo + i].axis(a);
    const double median = MedianInPlace(values_.data(), n);
    deviations_.resize(n);
    for (int i = 0; i < n; ++i) deviations_[i] = std::abs(window_[lo + i].axis(a) - median);
    const double sigma = kMadToSigma * MedianInPlace(deviations_.data(), n);
    const double x = window_[pos].axis(a);
    if (std::abs(x - median) > options_.n_sigma * sigma) {
      result.flagged_axes |= static_cast<uint8_t>(1u << a);
      result.sample.axis(a) = median;
    }
  }
  out->push_back(result);
}

void HampelDetector::Push(const ImuSample& raw, std::vector<DetectedSample>* out) {
  const int h = options_.half_window;
  window_.push_back(raw);
  if (static_cast<int>(window_.size()) - 1 - next_ < h) return;  // sample `next_` lacks its future half
  Emit(next_, out);
  ++next_;
  if (next_ > h) {  // keep h samples of past before the next one to emit
    window_.pop_front();
    --next_;
  }
}

void HampelDetector::Finish(std::vector<DetectedSample>* out) {
  for (; next_ < static_cast<int>(window_.size()); ++next_) Emit(next_, out);
  window_.clear();
  next_ = 0;
}

}  // namespace vigil::detectors
