// Linear (DLT) triangulation of one point seen in several calibrated views.
//
// Each view is a 3x4 projection P = [R_CX | p_CX] mapping a point in some frame X into the camera, and the
// observation is its normalized image coordinates (x/z, y/z). The result is the point in X.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace vigil::estimator {

using Projection = Eigen::Matrix<double, 3, 4>;

// Least-squares homogeneous solution of the 2N stacked equations. False for fewer than two views, a point at
// infinity, or a non-finite result. Depth is not checked here (see DepthIn).
bool TriangulateDlt(const std::vector<Projection>& views, const std::vector<Eigen::Vector2d>& observations,
                    Eigen::Vector3d* p_X);

// Depth (z in the camera) of p_X in view P.
inline double DepthIn(const Projection& P, const Eigen::Vector3d& p_X) {
  return P.row(2).head<3>().dot(p_X) + P(2, 3);
}

}  // namespace vigil::estimator
