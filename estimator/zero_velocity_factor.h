// Factors of the zero-velocity update on a stationary window interval (zero_velocity_detector.h).
//
// ZeroVelocityFactor, on one speed-bias block [v_W, b_a, b_g]:
//   r = v_W / velocity_std                                                   (3 residuals, linear)
// NoMotionFactor, on the two pose blocks [p_W, q_WB] of the interval's frames i and j:
//   r = [(p_j - p_i) / position_std ; 2 vec(q_i^-1 q_j) / rotation_std]      (6 residuals)
// With both velocities zero the IMU factor between the frames then asks its preintegrated deltas to be
// gravity alone: the gyro bias becomes the mean rotation rate, and the accelerometer bias what gravity
// does not explain along the held orientation.
// Jacobians with respect to the pose tangent (pose_manifold.h): with q_e = q_i^-1 q_j and the rotation
// perturbed on the right, d r_theta / d theta_j = Left(q_e) lower-right 3x3 and d r_theta / d theta_i =
// -Right(q_e) lower-right 3x3 (both over rotation_std).
#pragma once

#include <ceres/sized_cost_function.h>
#include <Eigen/Core>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {

class ZeroVelocityFactor : public ceres::SizedCostFunction<3, kSpeedBiasSize> {
 public:
  explicit ZeroVelocityFactor(double velocity_std_mps) : weight_(1.0 / velocity_std_mps) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  double weight_;
};

class NoMotionFactor : public ceres::SizedCostFunction<6, kPoseSize, kPoseSize> {
 public:
  NoMotionFactor(double position_std_m, double rotation_std_rad)
      : position_weight_(1.0 / position_std_m), rotation_weight_(1.0 / rotation_std_rad) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  double position_weight_;
  double rotation_weight_;
};

}  // namespace vigil::estimator
