// The covariance of the newest pose of the window, in the pose tangent [delta p_W, delta theta_B]
// (pose_manifold.h: position in the world frame, rotation perturbed on the right, in the body frame).
//
// The window's information matrix has four unobservable directions (position and yaw, the gauge), so the
// newest pose has a covariance only relative to something fixed. vigil fixes the oldest frame's position and
// yaw (GaugeFixedCovariance: the marginal of the newest pose given them) and then adds the oldest frame's own
// uncertainty along those four directions, as it was estimated when that frame was the newest
// (ChainGaugeCovariance). The cross-covariance between the two parts is neglected; the oldest frame's
// covariance is the one of its time as the newest frame, larger than what the window knows of it now.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vigil::estimator {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Information added along the gauge directions of the oldest pose to fix them: 1e8 / m^2 and 1e8 / rad^2,
// a std of 0.1 mm and 0.006 deg, four orders of magnitude stiffer than what a window knows of its poses.
inline constexpr double kGaugeInformation = 1e8;

// The newest pose's covariance from the information matrix `H` (tangent space, symmetric positive
// semi-definite) with the oldest pose's position and yaw held (its tangent block starts at `oldest_column`,
// its orientation is q_WB_oldest) and every other state marginalized; the newest pose's tangent block starts
// at `newest_column`. False when the conditioned matrix is not positive definite.
bool GaugeFixedCovariance(const Eigen::MatrixXd& H, int oldest_column, const Eigen::Quaterniond& q_WB_oldest,
                          int newest_column, Matrix6d* covariance);

// relative + G A oldest_global A^T G^T: the newest pose's covariance with the oldest frame's uncertainty
// along the gauge (A: its position and world yaw from its tangent; G: how moving the oldest frame's position
// and rotating it about the world z axis moves the newest pose).
Matrix6d ChainGaugeCovariance(const Matrix6d& relative, const Matrix6d& oldest_global,
                              const Eigen::Vector3d& p_W_oldest, const Eigen::Quaterniond& q_WB_oldest,
                              const Eigen::Vector3d& p_W_newest, const Eigen::Quaterniond& q_WB_newest);

}  // namespace vigil::estimator
