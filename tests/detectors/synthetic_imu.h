// Synthetic IMU streams for the detector tests: smooth motion (gravity, a vertical oscillation like the
// paper's ellipse, slow turns) plus white noise of the paper's densities at 200 Hz, and glitch injection.
#pragma once

#include <cmath>
#include <vector>

#include "core/random.h"
#include "core/types.h"
#include "detectors/detector_options.h"

namespace vigil::detectors::testing {

// vigil's normalized DTW (linear baseline removed), the variant these detection-quality tests were tuned on.
inline DtwOptions NormalizedDtw() {
  DtwOptions o;
  o.normalization = SliceNormalization::kLinear;
  return o;
}

inline ImuStream SyntheticImu(uint64_t seed, int samples, double noise_scale = 1.0) {
  Rng rng(seed, "synthetic_imu");
  const double gyro_sigma = 0.21 * noise_scale, acc_sigma = 0.27 * noise_scale;  // per sample at 200 Hz
  ImuStream imu(samples);
  for (int t = 0; t < samples; ++t) {
    const double s = t / 200.0;
    imu[t].t_ns = static_cast<int64_t>(t) * 5000000;
    imu[t].w_B = {0.1 * std::sin(s) + gyro_sigma * rng.Normal(),
                  0.2 * std::cos(s) + gyro_sigma * rng.Normal(), 0.157 + gyro_sigma * rng.Normal()};
    imu[t].a_B = {0.5 * std::cos(0.3 * s) + acc_sigma * rng.Normal(),
                  0.3 * std::sin(0.7 * s) + acc_sigma * rng.Normal(),
                  9.81 + 9.87 * std::sin(M_PI * s) + acc_sigma * rng.Normal()};
  }
  return imu;
}

// A 200 Hz stream whose accelerometer z reads az[t] (every other axis 0).
inline ImuStream AzSeries(const std::vector<double>& az) {
  ImuStream imu(az.size());
  for (std::size_t t = 0; t < az.size(); ++t) {
    imu[t].t_ns = static_cast<int64_t>(t) * 5000000;
    imu[t].a_B.z() = az[t];
  }
  return imu;
}

// Adds N(mean, std) to `axis` of each sample with probability `rate`; returns the records (glitches.csv
// rows).
inline std::vector<GlitchRecord> InjectGlitches(ImuStream* imu, uint64_t seed, double mean, double std,
                                                double rate, ImuAxis axis = ImuAxis::kAz) {
  Rng rng(seed, "synthetic_glitch");
  std::vector<GlitchRecord> records;
  for (ImuSample& s : *imu) {
    if (!rng.Bernoulli(rate)) continue;
    const double offset = rng.Normal(mean, std);
    s.axis(static_cast<int>(axis)) += offset;
    records.push_back({s.t_ns, axis, offset});
  }
  return records;
}

}  // namespace vigil::detectors::testing
