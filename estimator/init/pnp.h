// Camera pose from known 3-D points and their normalized image observations (perspective-n-point).
//
// The pose is T_CX (R_CX, p_CX): p_C = R_CX p_X + p_CX. Refinement is Gauss-Newton with Levenberg-Marquardt
// damping on the normalized-plane reprojection error, perturbing R_CX on the left (R <- Exp(dtheta) R), from
// an initial guess; inside the window SfM the guess is the neighbouring frame's pose, which is close at
// camera rate.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace vigil::estimator {

struct PnpOptions {
  int max_iterations = 20;
  double min_depth = 1e-3;  // points nearer than this (in the guess) are skipped
};

// Refines (R_CX, p_CX) in place. False for fewer than 4 points, a non-finite result, or a pose that leaves
// fewer than 4 points in front of the camera.
bool SolvePnp(const std::vector<Eigen::Vector3d>& points_X, const std::vector<Eigen::Vector2d>& observations,
              const PnpOptions& options, Eigen::Matrix3d* R_CX, Eigen::Vector3d* p_CX);

// Residual (normalized plane) and its Jacobian w.r.t. [dtheta, dp] for one point; exposed for the tests.
Eigen::Vector2d PnpResidual(const Eigen::Matrix3d& R_CX, const Eigen::Vector3d& p_CX,
                            const Eigen::Vector3d& p_X, const Eigen::Vector2d& observation,
                            Eigen::Matrix<double, 2, 6>* J);

}  // namespace vigil::estimator
