// Alignment of an estimated trajectory to its ground truth before the absolute error (rpg definitions).
//
// Finds (s, R, t) with p_gt ~ s R p_est + t in the least-squares sense over matched positions (Umeyama 1991):
//   sim3    rotation, translation and scale;
//   se3     rotation and translation (s = 1);
//   posyaw  rotation about z of W only, and translation (s = 1): the 4 degrees of freedom a visual-inertial
//           estimate cannot observe. With the centred positions, Cyaw = sum_k d_k m_k^T (d: estimate, m:
//           ground truth) and the best yaw is pi/2 - atan2(Cyaw00 + Cyaw11, Cyaw01 - Cyaw10);
//   none    the identity.
// With a single matched pair the rotation is unobservable: R = I and t = p_gt - p_est (s = 1). The scale of
// sim3 is 1 when the estimate does not spread (all positions equal).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "evaluation/evaluation_options.h"

namespace vigil::evaluation {

// x -> scale R x + t, mapping estimate coordinates into the ground-truth world frame.
struct SimilarityTransform {
  double scale = 1.0;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();

  Eigen::Vector3d Apply(const Eigen::Vector3d& p) const { return scale * (R * p) + t; }
  // The orientation of an aligned body: R q_WB.
  Eigen::Quaterniond Rotate(const Eigen::Quaterniond& q) const { return Eigen::Quaterniond(R) * q; }
};

// `p_est` and `p_gt` are matched pairs (same length, at least one; std::invalid_argument otherwise).
SimilarityTransform AlignPositions(const std::vector<Eigen::Vector3d>& p_est,
                                   const std::vector<Eigen::Vector3d>& p_gt, Alignment align);

}  // namespace vigil::evaluation
