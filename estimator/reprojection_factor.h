// Visual factor: a feature anchored in frame i by its normalized observation n_i and inverse depth rho,
//   p_Ci = [n_i, 1] / rho  ->  p_W = T_WB_i T_BC p_Ci  ->  p_Cj = (T_WB_j T_BC)^-1 p_W,
// observed in frame j at n_j; residual on the normalized plane, r = sqrt_info (p_Cj.xy / p_Cj.z - n_j), with
// sqrt_info = focal length / pixel std (the caller adds the Cauchy loss).
// Parameter blocks: pose_i (7), pose_j (7), inverse depth (1); analytic Jacobians (pose_manifold.h
// convention).
#pragma once

#include <ceres/sized_cost_function.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {

class ReprojectionFactor : public ceres::SizedCostFunction<2, kPoseSize, kPoseSize, 1> {
 public:
  ReprojectionFactor(const Eigen::Vector2d& n_i, const Eigen::Vector2d& n_j, const Eigen::Isometry3d& T_BC,
                     double sqrt_information);

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Eigen::Vector3d n_i_;
  Eigen::Vector2d n_j_;
  Eigen::Matrix3d R_BC_;
  Eigen::Vector3d p_BC_;
  double sqrt_information_;
};

}  // namespace vigil::estimator
