// An initialization window cut from a simulated recording (the simulator only generates test data).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/dataset.h"
#include "estimator/imu_interval.h"
#include "estimator/initializer.h"
#include "sim/simulator.h"

namespace vigil::estimator::testing {

// The paper scenario with the camera at 20 Hz (frame times fall on IMU samples), a short duration, and the
// given IMU noise scale (0: ideal IMU plus constant biases) and initial biases.
inline sim::SimOptions WindowSimOptions(double noise_scale, const Eigen::Vector3d& b_g,
                                        const Eigen::Vector3d& b_a) {
  sim::SimOptions o;
  o.duration_s = 3.0;
  o.camera.rate_hz = 20.0;
  o.imu.noise.gyro_noise_density *= noise_scale;
  o.imu.noise.accel_noise_density *= noise_scale;
  o.imu.noise.gyro_bias_random_walk *= noise_scale;
  o.imu.noise.accel_bias_random_walk *= noise_scale;
  o.imu.noise.initial_gyro_bias = {b_g.x(), b_g.y(), b_g.z()};
  o.imu.noise.initial_accel_bias = {b_a.x(), b_a.y(), b_a.z()};
  return o;
}

// Ground-truth state at the IMU sample with time t_ns (which must exist).
inline const NavState& TruthAt(const Dataset& data, int64_t t_ns) {
  for (const auto& s : data.groundtruth)
    if (s.t_ns == t_ns) return s;
  throw std::logic_error("no ground truth at a frame time");
}

// `count` consecutive camera frames from `first`: normalized features and the preintegrated IMU (measured
// stream, bias linearization point zero) from the previous frame.
inline std::vector<InitFrame> MakeWindow(const Dataset& data, std::size_t first, std::size_t count,
                                         const ImuNoiseDensities& noise) {
  std::vector<InitFrame> window;
  const double rate_hz = 1e9 / static_cast<double>(data.imu[1].t_ns - data.imu[0].t_ns);
  for (std::size_t k = first; k < first + count; ++k) {
    const CameraFrame& frame = data.frames.at(k);
    InitFrame f;
    f.t_ns = frame.t_ns;
    for (const auto& obs : frame.features) f.features_n[obs.id] = data.camera.Normalize(obs.uv_px);
    if (!window.empty())
      f.imu_from_prev =
          PreintegrateInterval(data.imu, window.back().t_ns, frame.t_ns, Eigen::Vector3d::Zero(),
                               Eigen::Vector3d::Zero(), noise, rate_hz);
    window.push_back(std::move(f));
  }
  return window;
}

}  // namespace vigil::estimator::testing
