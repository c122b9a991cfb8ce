// Seeded synthetic scenes for the initialization tests: random points in front of cameras with known poses.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/random.h"
#include "core/so3.h"

namespace vigil::estimator::testing {

inline Eigen::Vector3d RandomVector(Rng& rng, double scale) { return rng.NormalVector3() * scale; }

// Points uniformly in a box [-half, half]^2 x [z_min, z_max] of the frame they are returned in.
inline std::vector<Eigen::Vector3d> RandomPoints(Rng& rng, int count, double half_width, double z_min,
                                                 double z_max) {
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < count; ++i)
    pts.emplace_back(rng.Uniform(-half_width, half_width), rng.Uniform(-half_width, half_width),
                     rng.Uniform(z_min, z_max));
  return pts;
}

// Normalized image coordinates of p_X in a camera with pose T_CX, plus Gaussian noise of `std` (normalized).
inline Eigen::Vector2d Observe(const Eigen::Matrix3d& R_CX, const Eigen::Vector3d& p_CX,
                               const Eigen::Vector3d& p_X, Rng& rng, double std) {
  const Eigen::Vector3d p_C = R_CX * p_X + p_CX;
  const double du = rng.Normal(), dv = rng.Normal();  // drawn in this order
  return p_C.head<2>() / p_C.z() + Eigen::Vector2d(du, dv) * std;
}

inline double RotationErrorRad(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return AngleOf(Eigen::Quaterniond(a.transpose() * b));
}

}  // namespace vigil::estimator::testing
