// Normalized estimation error squared (NEES) of an estimated trajectory with per-pose covariances, defined as
// OpenVINS' ov_eval defines it: per pose, NEES = e^T P^-1 e separately for position (3 DoF) and orientation
// (3 DoF), with the ground truth brought into the estimate's frame by the trajectory alignment (the inverse
// of the one the ATE uses); the statistics are over the poses of the run (mean: ov_eval's per-run NEES).
//
// Errors, in the frames the covariance is expressed in (estimator/pose_covariance.h):
//   position     e_p = p_gt,est - p_est           (world frame of the estimate)
//   orientation  e_theta = Log(R_est^T R_gt,est)  (body frame: the estimate's right perturbation)
// where p_gt,est = R^T (p_gt - t) / s and R_gt,est = R^T R_gt for the alignment (s, R, t). ov_eval takes the
// orientation error against the unaligned ground truth, which is the same when the estimate's and the ground
// truth's frames coincide (its simulations); vigil aligns both, so that a yaw offset of the initialization is
// not counted as an orientation error. For a consistent estimator each per-pose NEES is chi-square
// distributed with 3 degrees of freedom: the mean is 3.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/types.h"
#include "evaluation/alignment.h"
#include "evaluation/association.h"
#include "evaluation/statistics.h"

namespace vigil::evaluation {

struct NeesStatistics {
  ErrorStatistics position, orientation;  // n = 0 without covariances
};

// `covariances` holds one 6x6 covariance [delta p_W, delta theta_B] per row of `est` (or is empty: nothing is
// computed). Poses without a ground-truth match, or whose covariance block is not finite and positive
// definite, are skipped.
NeesStatistics ComputeNees(const Trajectory& gt, const Trajectory& est,
                           const std::vector<Eigen::Matrix<double, 6, 6>>& covariances,
                           const SimilarityTransform& est_to_gt,
                           int64_t max_difference_ns = kDefaultMaxAssociationDifferenceNs);

}  // namespace vigil::evaluation
