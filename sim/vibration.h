// Band-limited platform vibration as an IMU senses it (imu.vibration).
//
// Each of the six axes carries a sum of K sinusoids, v(t) = sum_k A sin(2 pi f_k t + phi_k), with f_k drawn
// uniformly in [frequency_hz - bandwidth_hz / 2, frequency_hz + bandwidth_hz / 2] (a rotor whose speed
// wanders, a track whose tread frequency jitters) and phi_k uniformly in [0, 2 pi), independently per axis,
// from the stream (seed, "imu_vibration"). A = rms sqrt(2 / K) gives each axis the configured rms. The
// sinusoids are evaluated at the sample times, so a band above half the IMU rate aliases as it does in a real
// sampled sensor. Vibration is a measurement disturbance: it is added to the measured samples (imu.csv and
// imu_clean.csv), not to the ground truth.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sim/sim_options.h"

namespace vigil::sim {

class Vibration {
 public:
  Vibration(const ImuVibrationOptions& options, uint64_t seed);
  // The disturbance of the gyro [rad/s] and of the accelerometer [m/s^2] at t_s.
  void At(double t_s, Eigen::Vector3d* w_B, Eigen::Vector3d* a_B) const;

 private:
  struct Component {
    double omega_radps, phase_rad;
  };
  std::array<std::vector<Component>, 6> axes_;  // wx wy wz ax ay az
  double gyro_amplitude_ = 0.0, accel_amplitude_ = 0.0;
};

}  // namespace vigil::sim
