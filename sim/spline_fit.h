// Least-squares fit of a cumulative cubic B-spline on SO(3) x R^3 (sim/cumulative_bspline.h) to timed poses.
//
// With knots every dt from t = 0 to past the last pose, the control points minimize
//   sum_k |p(t_k) - p_k|^2 + |Log(R(t_k)^T R_k)|^2
//     + smoothing^2 sum_i |p_{i-1} - 2 p_i + p_{i+1}|^2 + |Log(R_{i-1}^T R_i) - Log(R_i^T R_{i+1})|^2
// (positions in metres, rotations in radians). The smoothing term (second differences of the control
// points, a discrete acceleration) keeps the problem well posed where knots have no pose nearby and damps
// the ground truth's own noise; 0 fits the poses as closely as the knots allow. Positions and rotations are
// independent problems; both are solved with Ceres (the rotations by Gauss-Newton on the quaternion
// manifold, from control rotations interpolated from the poses).
#pragma once

#include <vector>

#include "sim/cumulative_bspline.h"

namespace vigil::sim {

struct SplineFitPose {
  double t_s = 0.0;  // in [0, span]
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
};

// Fits a spline covering [0, poses.back().t_s] (at least 2 poses, increasing times, dt_s > 0).
CumulativeBSpline FitCumulativeBSpline(const std::vector<SplineFitPose>& poses, double dt_s,
                                       double smoothing);

}  // namespace vigil::sim
