// Visual factor of a landmark held as a point in W (window.oldest_tracks: points): the point p_W observed in
// frame j at its normalized observation n_j,
//   p_Cj = (T_WB_j T_BC)^-1 p_W,  r = sqrt_info (p_Cj.xy / p_Cj.z - n_j),
// with sqrt_info = focal length / pixel std (the caller adds the Cauchy loss), as ReprojectionFactor.
// Parameter blocks: pose_j (7), point (3); analytic Jacobians (pose_manifold.h convention).
#pragma once

#include <ceres/sized_cost_function.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {

inline constexpr int kPointSize = 3;

class PointReprojectionFactor : public ceres::SizedCostFunction<2, kPoseSize, kPointSize> {
 public:
  PointReprojectionFactor(const Eigen::Vector2d& n_j, const Eigen::Isometry3d& T_BC, double sqrt_information);

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Eigen::Vector2d n_j_;
  Eigen::Matrix3d R_BC_;
  Eigen::Vector3d p_BC_;
  double sqrt_information_;
};

}  // namespace vigil::estimator
