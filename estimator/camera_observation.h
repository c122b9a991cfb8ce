// A point in W seen by a frame's camera, as every visual factor evaluates it: the point in the frame's body
// and camera frames, its projection on the normalized plane, the residual against the observation,
// r = sqrt_info (p_C.xy / p_C.z - n), and its derivatives with respect to the point and to the observing
// pose (pose_manifold.h's tangent). ReprojectionFactor (the observing pose of an anchored depth) and
// PointReprojectionFactor (a landmark point) share it.
#pragma once

#include <Eigen/Core>

#include "core/so3.h"
#include "estimator/pose_manifold.h"

namespace vigil::estimator {

struct CameraObservation {
  // `p` and `R`: the observing frame's position and orientation in W; R_BC, p_BC: the camera in the body;
  // sqrt_information: focal length / pixel std.
  CameraObservation(const Eigen::Vector3d& p_W, const Eigen::Vector3d& p, const Eigen::Matrix3d& R,
                    const Eigen::Matrix3d& R_BC, const Eigen::Vector3d& p_BC, double sqrt_information)
      : p_B(R.transpose() * (p_W - p)), R_CB_(R_BC.transpose()), sqrt_information_(sqrt_information) {
    const Eigen::Vector3d p_C = R_BC.transpose() * (p_B - p_BC);
    inv_z = 1.0 / p_C.z();
    u = p_C.head<2>() * inv_z;
  }
  Eigen::Vector2d Residual(const Eigen::Vector2d& n) const { return sqrt_information_ * (u - n); }
  // d r / d p_B. Chain rule through p_C = R_CB (p_B - p_BC): d r / d p_C = sqrt_info / z [I2, -u], so
  // d r / d p_B = sqrt_info / z (rows 0, 1 of R_CB - u row 2 of R_CB).
  Eigen::Matrix<double, 2, 3> ResidualByBodyPoint() const {
    return (sqrt_information_ * inv_z) * (R_CB_.topRows<2>() - u * R_CB_.row(2));
  }
  // The observing pose's Jacobian (2 x kPoseSize, row-major at `jacobian`) from d r / d p_B and
  // d r / d p_W = d r / d p_B R^T.
  void ObservingPoseJacobian(const Eigen::Matrix<double, 2, 3>& d_r_d_pB,
                             const Eigen::Matrix<double, 2, 3>& d_r_d_pW, double* jacobian) const {
    Eigen::Map<Eigen::Matrix<double, 2, kPoseSize, Eigen::RowMajor>> jac(jacobian);
    jac.leftCols<3>() = -d_r_d_pW;
    jac.middleCols<3>(3) = d_r_d_pB * Skew(p_B);
    jac.col(6).setZero();
  }

  Eigen::Vector3d p_B;
  Eigen::Vector2d u;
  double inv_z = 0.0;

 private:
  Eigen::Matrix3d R_CB_;  // the camera's orientation in the body, inverted: p_C = R_CB (p_B - p_BC)
  double sqrt_information_;
};

}  // namespace vigil::estimator
