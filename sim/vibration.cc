#include "sim/vibration.h"

#include <cmath>

#include "core/random.h"

namespace vigil::sim {

Vibration::Vibration(const ImuVibrationOptions& options, uint64_t seed) {
  constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
  const int k = options.components;
  const double scale = std::sqrt(2.0 / static_cast<double>(k));
  gyro_amplitude_ = options.gyro_rms_radps * scale;
  accel_amplitude_ = options.accel_rms_mps2 * scale;
  Rng rng(seed, "imu_vibration");
  const double lo = options.frequency_hz - 0.5 * options.bandwidth_hz;
  for (auto& axis : axes_) {
    for (int i = 0; i < k; ++i) {
      const double f_hz = rng.Uniform(lo, lo + options.bandwidth_hz);  // draw order: frequency, then phase
      const double phase = rng.Uniform(0.0, kTwoPi);
      axis.push_back({kTwoPi * f_hz, phase});
    }
  }
}

void Vibration::At(double t_s, Eigen::Vector3d* w_B, Eigen::Vector3d* a_B) const {
  for (int a = 0; a < 6; ++a) {
    double sum = 0.0;
    for (const Component& c : axes_[static_cast<std::size_t>(a)])
      sum += std::sin(c.omega_radps * t_s + c.phase_rad);
    if (a < 3)
      (*w_B)[a] = gyro_amplitude_ * sum;
    else
      (*a_B)[a - 3] = accel_amplitude_ * sum;
  }
}

}  // namespace vigil::sim
