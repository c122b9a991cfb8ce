#include "estimator/point_reprojection_factor.h"

#include "estimator/camera_observation.h"

namespace vigil::estimator {

PointReprojectionFactor::PointReprojectionFactor(const Eigen::Vector2d& n_j, const Eigen::Isometry3d& T_BC,
                                                 double sqrt_information)
    : n_j_(n_j), R_BC_(T_BC.rotation()), p_BC_(T_BC.translation()), sqrt_information_(sqrt_information) {}

bool PointReprojectionFactor::Evaluate(double const* const* parameters, double* residuals,
                                       double** jacobians) const {
  const Eigen::Matrix3d R_j = PoseQ(parameters[0]).toRotationMatrix();
  const CameraObservation observation(Eigen::Map<const Eigen::Vector3d>(parameters[1]), PoseP(parameters[0]),
                                      R_j, R_BC_, p_BC_, sqrt_information_);
  Eigen::Map<Eigen::Vector2d> r(residuals);
  r = observation.Residual(n_j_);
  if (jacobians == nullptr) return true;
  const Eigen::Matrix<double, 2, 3> d_r_d_pBj = observation.ResidualByBodyPoint();
  const Eigen::Matrix<double, 2, 3> d_r_d_pW = d_r_d_pBj * R_j.transpose();
  if (jacobians[0] != nullptr) observation.ObservingPoseJacobian(d_r_d_pBj, d_r_d_pW, jacobians[0]);
  if (jacobians[1] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, 2, kPointSize, Eigen::RowMajor>> jac(jacobians[1]);
    jac = d_r_d_pW;
  }
  return true;
}

}  // namespace vigil::estimator
