#include "estimator/pose_manifold.h"

#include "core/so3.h"

namespace vigil::estimator {

bool PoseManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  Eigen::Map<Eigen::Vector3d> p(x_plus_delta);
  Eigen::Map<Eigen::Quaterniond> q(x_plus_delta + 3);
  const Eigen::Map<const Eigen::Vector3d> dp(delta), dtheta(delta + 3);
  p = PoseP(x) + dp;
  q = (PoseQ(x) * ExpQ(dtheta)).normalized();
  return true;
}

bool PoseManifold::PlusJacobian(const double* /*x*/, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, kPoseSize, kPoseTangentSize, Eigen::RowMajor>> J(jacobian);
  J.setZero();
  J.topRows<kPoseTangentSize>().setIdentity();
  return true;
}

bool PoseManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  Eigen::Map<Eigen::Vector3d> dp(y_minus_x), dtheta(y_minus_x + 3);
  dp = PoseP(y) - PoseP(x);
  dtheta = LogQ(PoseQ(x).conjugate() * PoseQ(y));
  return true;
}

bool PoseManifold::MinusJacobian(const double* /*x*/, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, kPoseTangentSize, kPoseSize, Eigen::RowMajor>> J(jacobian);
  J.setZero();
  J.leftCols<kPoseTangentSize>().setIdentity();
  return true;
}

Eigen::Matrix4d QuatLeft(const Eigen::Quaterniond& q) {
  Eigen::Matrix4d m;
  m(0, 0) = q.w();
  m.block<1, 3>(0, 1) = -q.vec().transpose();
  m.block<3, 1>(1, 0) = q.vec();
  m.block<3, 3>(1, 1) = q.w() * Eigen::Matrix3d::Identity() + Skew(q.vec());
  return m;
}

Eigen::Matrix4d QuatRight(const Eigen::Quaterniond& q) {
  Eigen::Matrix4d m;
  m(0, 0) = q.w();
  m.block<1, 3>(0, 1) = -q.vec().transpose();
  m.block<3, 1>(1, 0) = q.vec();
  m.block<3, 3>(1, 1) = q.w() * Eigen::Matrix3d::Identity() - Skew(q.vec());
  return m;
}

}  // namespace vigil::estimator
