#include "estimator/reprojection_factor.h"

#include "core/so3.h"

namespace vigil::estimator {

ReprojectionFactor::ReprojectionFactor(const Eigen::Vector2d& n_i, const Eigen::Vector2d& n_j,
                                       const Eigen::Isometry3d& T_BC, double sqrt_information)
    : n_i_(n_i.x(), n_i.y(), 1.0),
      n_j_(n_j),
      R_BC_(T_BC.rotation()),
      p_BC_(T_BC.translation()),
      sqrt_information_(sqrt_information) {}

bool ReprojectionFactor::Evaluate(double const* const* parameters, double* residuals,
                                  double** jacobians) const {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  // Pose quaternions are unit (PoseManifold::Plus and every state write normalize them).
  const Vector3d p_i = PoseP(parameters[0]);
  const Matrix3d R_i = PoseQ(parameters[0]).toRotationMatrix();
  const Vector3d p_j = PoseP(parameters[1]);
  const Matrix3d R_j = PoseQ(parameters[1]).toRotationMatrix();
  const double inv_rho = 1.0 / parameters[2][0];

  const Vector3d p_Bi = R_BC_ * (n_i_ * inv_rho) + p_BC_;
  const Vector3d p_W = R_i * p_Bi + p_i;
  const Vector3d p_Bj = R_j.transpose() * (p_W - p_j);
  const Vector3d p_Cj = R_BC_.transpose() * (p_Bj - p_BC_);
  const double inv_z = 1.0 / p_Cj.z();

  const Eigen::Vector2d u = p_Cj.head<2>() * inv_z;  // the projection
  Eigen::Map<Eigen::Vector2d> r(residuals);
  r = sqrt_information_ * (u - n_j_);
  if (jacobians == nullptr) return true;

  // Chain rule from the residual back through p_Cj = R_CB (R_j^T (p_W - p_j) - p_BC): d r / d p_Cj =
  // sqrt_info / z [I2, -u], so d r / d p_Bj = sqrt_info / z (rows 0, 1 of R_CB - u row 2 of R_CB).
  const auto R_CB = R_BC_.transpose();
  const Eigen::Matrix<double, 2, 3> d_r_d_pBj =
      (sqrt_information_ * inv_z) * (R_CB.topRows<2>() - u * R_CB.row(2));
  const Eigen::Matrix<double, 2, 3> d_r_d_pW = d_r_d_pBj * R_j.transpose();
  const Eigen::Matrix<double, 2, 3> d_r_d_pBi = d_r_d_pW * R_i;
  using RowMajor2x7 = Eigen::Matrix<double, 2, 7, Eigen::RowMajor>;
  if (jacobians[0] != nullptr) {
    Eigen::Map<RowMajor2x7> jac(jacobians[0]);
    jac.leftCols<3>() = d_r_d_pW;
    jac.middleCols<3>(3) = -d_r_d_pBi * Skew(p_Bi);
    jac.col(6).setZero();
  }
  if (jacobians[1] != nullptr) {
    Eigen::Map<RowMajor2x7> jac(jacobians[1]);
    jac.leftCols<3>() = -d_r_d_pW;
    jac.middleCols<3>(3) = d_r_d_pBj * Skew(p_Bj);
    jac.col(6).setZero();
  }
  if (jacobians[2] != nullptr) {
    // d p_Bi / d rho = -R_BC n_i / rho^2.
    Eigen::Map<Eigen::Vector2d> jac(jacobians[2]);
    jac = d_r_d_pBi * (R_BC_ * n_i_) * (-inv_rho * inv_rho);
  }
  return true;
}

}  // namespace vigil::estimator
