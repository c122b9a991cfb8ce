// Rotation helpers on SO(3) shared by the simulator, the estimator and the evaluation.
// Rotation vectors are in radians; quaternions are Hamilton, unit norm.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vigil {

// [v]x, so that Skew(a) * b = a.cross(b). Inline: the factors call it per residual evaluation.
inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(),  //
      v.z(), 0.0, -v.x(),   //
      -v.y(), v.x(), 0.0;
  return m;
}
// Exponential map: unit quaternion of the rotation by |phi| about phi / |phi| (accurate for small phi).
Eigen::Quaterniond ExpQ(const Eigen::Vector3d& phi);
// Logarithm: rotation vector of a unit quaternion, angle in [0, pi].
Eigen::Vector3d LogQ(const Eigen::Quaterniond& q);
// Right Jacobian of SO(3) and its inverse.
Eigen::Matrix3d RightJacobian(const Eigen::Vector3d& phi);
Eigen::Matrix3d RightJacobianInverse(const Eigen::Vector3d& phi);
// Yaw (rotation about z of W, ZYX convention) of a rotation, in radians.
double YawOf(const Eigen::Matrix3d& R);
// Rotation about z by `yaw` radians.
Eigen::Matrix3d RotZ(double yaw);
// Angle of a rotation in radians, in [0, pi].
double AngleOf(const Eigen::Quaterniond& q);

}  // namespace vigil
