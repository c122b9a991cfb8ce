// Test/bench helpers: estimator input from the simulator, and the ATE of an estimate after posyaw alignment
// (4-DoF: yaw + translation, as rpg_trajectory_evaluation's posyaw), for the estimator's own accuracy checks.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/interpolation.h"
#include "core/so3.h"
#include "estimator/estimator_input.h"
#include "sim/simulator.h"

namespace vigil::estimator::testing {

inline EstimatorInput InputFromSimulation(const sim::SimOptions& options, const Dataset& data,
                                          uint64_t seed) {
  EstimatorInput input;
  input.imu = data.imu;
  input.frames = data.frames;
  input.camera = data.camera;
  input.imu_noise.gyro_noise_density = options.imu.noise.gyro_noise_density;
  input.imu_noise.accel_noise_density = options.imu.noise.accel_noise_density;
  input.imu_noise.gyro_bias_random_walk = options.imu.noise.gyro_bias_random_walk;
  input.imu_noise.accel_bias_random_walk = options.imu.noise.accel_bias_random_walk;
  input.gravity_mps2 = options.gravity_mps2;
  input.groundtruth = data.groundtruth;
  input.seed = seed;
  return input;
}

// RMSE of the position error after the best yaw + translation alignment of `estimate` onto the ground truth.
inline double PosYawAteRmse(const std::vector<NavState>& estimate, const std::vector<NavState>& groundtruth) {
  std::vector<Eigen::Vector3d> est, gt;
  for (const NavState& s : estimate) {
    NavState truth;
    if (!InterpolateNavState(groundtruth, s.t_ns, &truth)) continue;
    est.push_back(s.p_W);
    gt.push_back(truth.p_W);
  }
  if (est.empty()) return std::nan("");
  Eigen::Vector3d mean_est = Eigen::Vector3d::Zero(), mean_gt = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < est.size(); ++i) {
    mean_est += est[i] / static_cast<double>(est.size());
    mean_gt += gt[i] / static_cast<double>(gt.size());
  }
  double sin_sum = 0.0, cos_sum = 0.0;
  for (std::size_t i = 0; i < est.size(); ++i) {
    const Eigen::Vector3d e = est[i] - mean_est, g = gt[i] - mean_gt;
    cos_sum += g.x() * e.x() + g.y() * e.y();
    sin_sum += g.y() * e.x() - g.x() * e.y();
  }
  const Eigen::Matrix3d R = RotZ(std::atan2(sin_sum, cos_sum));
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < est.size(); ++i)
    sum_sq += (gt[i] - mean_gt - R * (est[i] - mean_est)).squaredNorm();
  return std::sqrt(sum_sq / static_cast<double>(est.size()));
}

}  // namespace vigil::estimator::testing
