// The Hampel filter: a classic robust spike detector, streaming with a latency of h samples.
//
// Per axis, over the centred window of samples [t - h, t + h] (truncated at both ends of the stream), the
// median m and sigma = 1.4826 x MAD (median absolute deviation; 1.4826 makes it the standard deviation for
// Gaussian data). The value x_t is abnormal when |x_t - m| > n_sigma x sigma and is replaced by m. The window
// always holds the raw values (a replacement does not feed back).
#pragma once

#include <deque>
#include <vector>

#include "detectors/detector.h"

namespace vigil::detectors {

class HampelDetector final : public Detector {
 public:
  explicit HampelDetector(const HampelOptions& options);

  void Push(const ImuSample& raw, std::vector<DetectedSample>* out) override;
  void Finish(std::vector<DetectedSample>* out) override;
  int latency_samples() const override { return options_.half_window; }

 private:
  // Emits the sample at position `pos` of window_ using the window's samples in [pos - h, pos + h].
  void Emit(int pos, std::vector<DetectedSample>* out);

  HampelOptions options_;
  std::deque<ImuSample> window_;  // raw samples from (next to emit - h) to the newest
  int next_ = 0;                  // position in window_ of the next sample to emit
  std::vector<double> values_, deviations_;
};

}  // namespace vigil::detectors
