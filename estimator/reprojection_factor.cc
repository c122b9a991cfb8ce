#include "estimator/reprojection_factor.h"

#include "core/so3.h"
#include "estimator/camera_observation.h"

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
  const CameraObservation observation(p_W, p_j, R_j, R_BC_, p_BC_, sqrt_information_);
  Eigen::Map<Eigen::Vector2d> r(residuals);
  r = observation.Residual(n_j_);
  if (jacobians == nullptr) return true;

  const Eigen::Matrix<double, 2, 3> d_r_d_pBj = observation.ResidualByBodyPoint();
  const Eigen::Matrix<double, 2, 3> d_r_d_pW = d_r_d_pBj * R_j.transpose();
  const Eigen::Matrix<double, 2, 3> d_r_d_pBi = d_r_d_pW * R_i;
  if (jacobians[0] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, 2, kPoseSize, Eigen::RowMajor>> jac(jacobians[0]);
    jac.leftCols<3>() = d_r_d_pW;
    jac.middleCols<3>(3) = -d_r_d_pBi * Skew(p_Bi);
    jac.col(6).setZero();
  }
  if (jacobians[1] != nullptr) observation.ObservingPoseJacobian(d_r_d_pBj, d_r_d_pW, jacobians[1]);
  if (jacobians[2] != nullptr) {
    // d p_Bi / d rho = -R_BC n_i / rho^2.
    Eigen::Map<Eigen::Vector2d> jac(jacobians[2]);
    jac = d_r_d_pBi * (R_BC_ * n_i_) * (-inv_rho * inv_rho);
  }
  return true;
}

}  // namespace vigil::estimator
