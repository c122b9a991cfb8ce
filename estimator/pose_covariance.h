// The covariance of the newest pose of the window, in the pose tangent [delta p_W, delta theta_B]
// (pose_manifold.h: position in the world frame, rotation perturbed on the right, in the body frame).
//
// A visual-inertial window cannot observe its position and yaw (four gauge directions), so a pose has a
// covariance only relative to something held fixed. vigil holds the position and yaw of the run's first
// frame, as a filter started from a known pose does: its covariance is the uncertainty accumulated since
// the start. The first frame is the oldest of the window until it is marginalized; the estimator then
// carries the holding information on in a second marginalization prior (the one of the solve plus the gauge,
// Estimator::anchored_prior_), so the newest pose's marginal of the window information with that prior is
// its covariance relative to the run's first frame, cross-covariances included. Before the first
// marginalization the oldest frame is held directly (AddGaugeInformation).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimator/marginalization.h"

namespace vigil::estimator {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Information added along the gauge directions of the first pose to hold them: 1e8 / m^2 and 1e8 / rad^2,
// a std of 0.1 mm and 0.006 deg, four orders of magnitude stiffer than what a window knows of its poses.
inline constexpr double kGaugeInformation = 1e8;

// A linear prior on the pose block at `pose` (kPoseSize doubles, at its current value) that holds its
// position and its yaw about the world z axis with kGaugeInformation; roll and pitch stay free.
LinearPrior GaugePrior(double* pose);

// Adds the information of GaugePrior at the pose whose tangent block starts at `column` of `H`.
void AddGaugeInformation(const Eigen::Quaterniond& q_WB, int column, Eigen::MatrixXd* H);

}  // namespace vigil::estimator
