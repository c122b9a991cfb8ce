// Prior on the IMU biases of one frame: the initializer's bias estimate with a configured uncertainty.
//
// The factor acts on a speed-bias block [v_W (3), b_a (3), b_g (3)] and leaves the velocity free:
//   r = [(b_a - b_a0) / accel_bias_std ; (b_g - b_g0) / gyro_bias_std]   (6 residuals).
// It carries the knowledge an IMU datasheet or a calibration gives before any motion (turn-on bias
// repeatability), which sliding-window data over the first second or two cannot replace: with few keyframes
// the accelerometer bias trades off against gravity direction, velocity and scale, and what the first windows
// get wrong is frozen into the marginalization prior. A constant Jacobian (a linear factor), so marginalizing
// it is exact. A std of 0 switches that half off (its rows are zero).
#pragma once

#include <ceres/sized_cost_function.h>
#include <Eigen/Core>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {

class BiasPriorFactor : public ceres::SizedCostFunction<6, kSpeedBiasSize> {
 public:
  BiasPriorFactor(const Eigen::Vector3d& b_a0, const Eigen::Vector3d& b_g0, double accel_bias_std,
                  double gyro_bias_std);

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Eigen::Vector3d b_a0_, b_g0_;
  double accel_weight_;  // 1 / accel_bias_std, 0 when switched off
  double gyro_weight_;   // 1 / gyro_bias_std, 0 when switched off
};

}  // namespace vigil::estimator
