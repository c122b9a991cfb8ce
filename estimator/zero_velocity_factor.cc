#include "estimator/zero_velocity_factor.h"

namespace vigil::estimator {

bool ZeroVelocityFactor::Evaluate(double const* const* parameters, double* residuals,
                                  double** jacobians) const {
  Eigen::Map<Eigen::Vector3d> r(residuals);
  r = weight_ * Eigen::Map<const Eigen::Vector3d>(parameters[0]);
  if (jacobians != nullptr && jacobians[0] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, 3, kSpeedBiasSize, Eigen::RowMajor>> J(jacobians[0]);
    J.setZero();
    J.leftCols<3>().diagonal().setConstant(weight_);
  }
  return true;
}

bool NoMotionFactor::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const Eigen::Quaterniond q_i = PoseQ(parameters[0]);
  const Eigen::Quaterniond q_j = PoseQ(parameters[1]);
  const Eigen::Quaterniond q_e = q_i.conjugate() * q_j;
  Eigen::Map<Eigen::Matrix<double, 6, 1>> r(residuals);
  r.head<3>() = position_weight_ * (PoseP(parameters[1]) - PoseP(parameters[0]));
  r.tail<3>() = rotation_weight_ * 2.0 * q_e.vec();
  if (jacobians == nullptr) return true;
  using PoseJacobian = Eigen::Matrix<double, 6, kPoseSize, Eigen::RowMajor>;
  if (jacobians[0] != nullptr) {
    Eigen::Map<PoseJacobian> J(jacobians[0]);
    J.setZero();
    J.block<3, 3>(0, 0).diagonal().setConstant(-position_weight_);
    J.block<3, 3>(3, 3) = -rotation_weight_ * QuatRight(q_e).bottomRightCorner<3, 3>();
  }
  if (jacobians[1] != nullptr) {
    Eigen::Map<PoseJacobian> J(jacobians[1]);
    J.setZero();
    J.block<3, 3>(0, 0).diagonal().setConstant(position_weight_);
    J.block<3, 3>(3, 3) = rotation_weight_ * QuatLeft(q_e).bottomRightCorner<3, 3>();
  }
  return true;
}

}  // namespace vigil::estimator
