#include "estimator/imu_trust.h"

#include <algorithm>
#include <cmath>

namespace vigil::estimator {

bool IsClipped(const SaturationAwareOptions& options, const ImuSample& s) {
  const double keep = 1.0 - options.tolerance_fraction;
  const double accel_limit = options.accel_range_mps2 * keep;
  const double gyro_limit = options.gyro_range_dps * M_PI / 180.0 * keep;
  for (int i = 0; i < kNumImuAxes; ++i) {
    const double limit = i < 3 ? gyro_limit : accel_limit;
    if (limit > 0.0 && std::abs(s.axis(i)) >= limit) return true;
  }
  return false;
}

ImuTrust ComputeImuTrust(const MitigationOptions& options, const ImuStream& imu,
                         const std::vector<uint8_t>& flagged) {
  ImuTrust trust;
  const bool inflate = options.inflate.enabled && !flagged.empty();
  const bool saturation = options.saturation.enabled;
  if (!inflate && !saturation) return trust;
  std::vector<double> scale(imu.size(), 1.0);
  for (std::size_t k = 0; k < imu.size(); ++k) {
    if (inflate && flagged[k]) {
      scale[k] = options.inflate.variance_factor;
      ++trust.inflated_samples;
    }
    if (saturation && IsClipped(options.saturation, imu[k])) {
      scale[k] = std::max(scale[k], options.saturation.variance_factor);
      ++trust.clipped_samples;
    }
  }
  if (trust.inflated_samples + trust.clipped_samples > 0) trust.variance_scale = std::move(scale);
  return trust;
}

}  // namespace vigil::estimator
