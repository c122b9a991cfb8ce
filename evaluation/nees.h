// Normalized estimation error squared (NEES) of an estimated trajectory with per-pose covariances, as
// OpenVINS' ov_eval defines it: per pose, NEES = e^T P^-1 e separately for position (3 DoF) and orientation
// (3 DoF), with the ground truth brought into the estimate's frame by an alignment; the statistics are over
// the poses of the run (mean: ov_eval's per-run NEES).
//
// Errors, in the frames the covariance is expressed in (estimator/pose_covariance.h):
//   position     e_p = p_gt,est - p_est           (world frame of the estimate)
//   orientation  e_theta = Log(R_est^T R_gt,est)  (body frame: the estimate's right perturbation)
// where p_gt,est = R^T (p_gt - t) / s and R_gt,est = R^T R_gt for the alignment (s, R, t).
//
// The alignment must hold the same gauge as the covariance, or the NEES measures the alignment: the
// estimator's covariance is relative to the position and yaw of the run's first frame, so GaugeAlignment
// aligns the two trajectories at their first matched pose (position and yaw). A least-squares alignment
// over the whole run (the ATE's) removes most of the drift that the covariance accounts for, and the NEES
// comes out far below 3 for a consistent estimator. For a consistent estimator each per-pose NEES is
// chi-square distributed with 3 degrees of freedom: the mean is 3.
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

// The alignment (s = 1, a rotation about z, a translation) that maps the estimate's first pose with a
// ground-truth match and a finite covariance onto that ground-truth pose, in position and yaw: the gauge of
// the estimator's covariance. The identity when there is no such pose.
SimilarityTransform GaugeAlignment(const Trajectory& gt, const Trajectory& est,
                                   const std::vector<Eigen::Matrix<double, 6, 6>>& covariances,
                                   int64_t max_difference_ns = kDefaultMaxAssociationDifferenceNs);

}  // namespace vigil::evaluation
