#include "sim/quantization.h"

#include <cmath>

namespace vigil::sim {

void ApplyQuantization(const QuantizationOptions& options, ImuStream* imu) {
  const double gyro_lsb = options.gyro_lsb_dps * M_PI / 180.0;
  const double accel_lsb = options.accel_lsb_mps2;
  if (gyro_lsb <= 0.0 && accel_lsb <= 0.0) return;
  for (ImuSample& s : *imu) {
    for (int i = 0; i < kNumImuAxes; ++i) {
      const double lsb = i < 3 ? gyro_lsb : accel_lsb;
      if (lsb > 0.0) s.axis(i) = lsb * std::round(s.axis(i) / lsb);
    }
  }
}

}  // namespace vigil::sim
