#include "core/so3.h"

#include <cmath>

namespace vigil {

Eigen::Quaterniond ExpQ(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const double half = 0.5 * theta;
  // sin(half)/theta, by its Taylor series near 0.
  const double k = theta < 1e-8 ? 0.5 - theta * theta / 48.0 : std::sin(half) / theta;
  return Eigen::Quaterniond(std::cos(half), k * phi.x(), k * phi.y(), k * phi.z()).normalized();
}

Eigen::Vector3d LogQ(const Eigen::Quaterniond& q_in) {
  Eigen::Quaterniond q = q_in.normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const Eigen::Vector3d v = q.vec();
  const double s = v.norm();
  if (s < 1e-10) return 2.0 * v / q.w();
  const double theta = 2.0 * std::atan2(s, q.w());
  return theta / s * v;
}

Eigen::Matrix3d RightJacobian(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d K = Skew(phi);
  if (theta < 1e-6) return Eigen::Matrix3d::Identity() - 0.5 * K + K * K / 6.0;
  const double t2 = theta * theta;
  return Eigen::Matrix3d::Identity() - (1.0 - std::cos(theta)) / t2 * K +
         (theta - std::sin(theta)) / (t2 * theta) * K * K;
}

Eigen::Matrix3d RightJacobianInverse(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d K = Skew(phi);
  if (theta < 1e-6) return Eigen::Matrix3d::Identity() + 0.5 * K + K * K / 12.0;
  const double t2 = theta * theta;
  return Eigen::Matrix3d::Identity() + 0.5 * K +
         (1.0 / t2 - (1.0 + std::cos(theta)) / (2.0 * theta * std::sin(theta))) * K * K;
}

double YawOf(const Eigen::Matrix3d& R) { return std::atan2(R(1, 0), R(0, 0)); }

Eigen::Matrix3d RotZ(double yaw) {
  return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

double AngleOf(const Eigen::Quaterniond& q) { return LogQ(q).norm(); }

}  // namespace vigil
