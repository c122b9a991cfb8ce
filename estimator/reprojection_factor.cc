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
  const Vector3d p_i = PoseP(parameters[0]);
  const Matrix3d R_i = PoseQ(parameters[0]).normalized().toRotationMatrix();
  const Vector3d p_j = PoseP(parameters[1]);
  const Matrix3d R_j = PoseQ(parameters[1]).normalized().toRotationMatrix();
  const double rho = parameters[2][0];

  const Vector3d p_Ci = n_i_ / rho;
  const Vector3d p_Bi = R_BC_ * p_Ci + p_BC_;
  const Vector3d p_W = R_i * p_Bi + p_i;
  const Vector3d p_Bj = R_j.transpose() * (p_W - p_j);
  const Vector3d p_Cj = R_BC_.transpose() * (p_Bj - p_BC_);
  const double z = p_Cj.z();

  Eigen::Map<Eigen::Vector2d> r(residuals);
  r = sqrt_information_ * (p_Cj.head<2>() / z - n_j_);
  if (jacobians == nullptr) return true;

  Eigen::Matrix<double, 2, 3> d_r_d_pCj;
  d_r_d_pCj << 1.0 / z, 0.0, -p_Cj.x() / (z * z),  //
      0.0, 1.0 / z, -p_Cj.y() / (z * z);
  d_r_d_pCj *= sqrt_information_;
  // Chain rule through p_Cj = R_CW_j (p_W - p_j) + const: d r / d p_W, and its rotation into B_i.
  const Eigen::Matrix<double, 2, 3> d_r_d_pW = d_r_d_pCj * (R_BC_.transpose() * R_j.transpose());
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
    jac.middleCols<3>(3) = (d_r_d_pCj * R_BC_.transpose()) * Skew(p_Bj);
    jac.col(6).setZero();
  }
  if (jacobians[2] != nullptr) {
    Eigen::Map<Eigen::Vector2d> jac(jacobians[2]);
    jac = d_r_d_pBi * (R_BC_ * (-n_i_ / (rho * rho)));
  }
  return true;
}

}  // namespace vigil::estimator
