// IMU factor between consecutive window frames i and j: 15-dim residual of the preintegrated deltas,
//   r_p  = R_i^T (p_j - p_i - v_i T - 1/2 g_W T^2) - dp(b_i)
//   r_q  = 2 vec(dq(b_g,i)^-1 * q_i^-1 * q_j)
//   r_v  = R_i^T (v_j - v_i - g_W T) - dv(b_i)
//   r_ba = b_a,j - b_a,i,  r_bg = b_g,j - b_g,i
// (deltas bias-corrected to first order), whitened by the square root of the inverse preintegration
// covariance. Parameter blocks: pose_i (7), speed_bias_i (9), pose_j (7), speed_bias_j (9); analytic
// Jacobians in the tangent convention of pose_manifold.h. A gated factor (imu_gating.h) has its covariance
// inflated by a factor k: residual and Jacobians are then multiplied by 1 / sqrt(k).
#pragma once

#include <cmath>

#include <ceres/sized_cost_function.h>
#include <Eigen/Core>

#include "estimator/pose_manifold.h"
#include "estimator/preintegration.h"

namespace vigil::estimator {

class ImuFactor : public ceres::SizedCostFunction<15, kPoseSize, kSpeedBiasSize, kPoseSize, kSpeedBiasSize> {
 public:
  // `pre` must outlive the factor and stay unchanged while it is used.
  ImuFactor(const Preintegration& pre, const Eigen::Vector3d& g_W);

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

  // Multiplies the factor's covariance by `factor` (>= 1; 1 restores it).
  void InflateCovariance(double factor) { weight_ = 1.0 / std::sqrt(factor); }
  double covariance_inflation() const { return 1.0 / (weight_ * weight_); }

 private:
  const Preintegration& pre_;
  Eigen::Vector3d g_W_;
  double weight_ = 1.0;  // 1 / sqrt(covariance inflation)
};

}  // namespace vigil::estimator
