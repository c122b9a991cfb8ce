// Parameter blocks of the window and the manifold of a pose.
//
// Pose block: 7 doubles [p_W (3), q_WB (x, y, z, w)], tangent [delta p (3), delta theta (3)] with the
// rotation perturbed on the right: q <- q * Exp(delta theta). Speed-bias block: 9 doubles [v_W, b_a, b_g].
//
// Jacobian convention shared by every factor of this estimator: a factor writes its Jacobian with respect to
// the 6-dim tangent of a pose into the first 6 columns of the 7-column block and zeros into the last;
// PlusJacobian is therefore [I6; 0], so Ceres' product (ambient Jacobian) x (PlusJacobian) is the tangent
// Jacobian.
#pragma once

#include <ceres/manifold.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vigil::estimator {

inline constexpr int kPoseSize = 7;
inline constexpr int kPoseTangentSize = 6;
inline constexpr int kSpeedBiasSize = 9;

// Tangent size of a parameter block of the window from its ambient size (a pose's 7 -> 6; vectors: the same).
inline constexpr int TangentSizeOf(int ambient_size) {
  return ambient_size == kPoseSize ? kPoseTangentSize : ambient_size;
}

class PoseManifold : public ceres::Manifold {
 public:
  int AmbientSize() const override { return kPoseSize; }
  int TangentSize() const override { return kPoseTangentSize; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;
};

// Views of a pose block.
inline Eigen::Map<const Eigen::Vector3d> PoseP(const double* pose) {
  return Eigen::Map<const Eigen::Vector3d>(pose);
}
inline Eigen::Map<const Eigen::Quaterniond> PoseQ(const double* pose) {
  return Eigen::Map<const Eigen::Quaterniond>(pose + 3);
}

// Quaternion multiplication as matrices on (w, x, y, z) coefficient vectors: p * q = Left(p) q = Right(q) p.
Eigen::Matrix4d QuatLeft(const Eigen::Quaterniond& q);
Eigen::Matrix4d QuatRight(const Eigen::Quaterniond& q);

}  // namespace vigil::estimator
