#include "estimator/point_reprojection_factor.h"

#include "core/so3.h"

namespace vigil::estimator {

PointReprojectionFactor::PointReprojectionFactor(const Eigen::Vector2d& n_j, const Eigen::Isometry3d& T_BC,
                                                 double sqrt_information)
    : n_j_(n_j), R_BC_(T_BC.rotation()), p_BC_(T_BC.translation()), sqrt_information_(sqrt_information) {}

bool PointReprojectionFactor::Evaluate(double const* const* parameters, double* residuals,
                                       double** jacobians) const {
  const Eigen::Vector3d p_j = PoseP(parameters[0]);
  const Eigen::Matrix3d R_j = PoseQ(parameters[0]).toRotationMatrix();
  const Eigen::Map<const Eigen::Vector3d> p_W(parameters[1]);
  const Eigen::Vector3d p_Bj = R_j.transpose() * (p_W - p_j);
  const Eigen::Vector3d p_Cj = R_BC_.transpose() * (p_Bj - p_BC_);
  const double inv_z = 1.0 / p_Cj.z();
  const Eigen::Vector2d u = p_Cj.head<2>() * inv_z;
  Eigen::Map<Eigen::Vector2d> r(residuals);
  r = sqrt_information_ * (u - n_j_);
  if (jacobians == nullptr) return true;
  // As ReprojectionFactor's observing pose: d r / d p_Bj = sqrt_info / z (rows 0, 1 of R_CB - u row 2).
  const auto R_CB = R_BC_.transpose();
  const Eigen::Matrix<double, 2, 3> d_r_d_pBj =
      (sqrt_information_ * inv_z) * (R_CB.topRows<2>() - u * R_CB.row(2));
  const Eigen::Matrix<double, 2, 3> d_r_d_pW = d_r_d_pBj * R_j.transpose();
  if (jacobians[0] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, 2, kPoseSize, Eigen::RowMajor>> jac(jacobians[0]);
    jac.leftCols<3>() = -d_r_d_pW;
    jac.middleCols<3>(3) = d_r_d_pBj * Skew(p_Bj);
    jac.col(6).setZero();
  }
  if (jacobians[1] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, 2, kPointSize, Eigen::RowMajor>> jac(jacobians[1]);
    jac = d_r_d_pW;
  }
  return true;
}

}  // namespace vigil::estimator
