#include "plots/trajectory_alignment.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <Eigen/Geometry>

namespace vigil::plots {
namespace {

constexpr int64_t kMatchToleranceNs = 1'000'000;

}  // namespace

Trajectory AlignForDisplay(const Trajectory& estimate, const Trajectory& groundtruth,
                           experiments::Alignment alignment) {
  Trajectory matched;
  std::vector<Eigen::Vector3d> p_est, p_gt;
  std::size_t j = 0;
  for (const StampedPose& e : estimate) {
    while (j + 1 < groundtruth.size() &&
           std::llabs(groundtruth[j + 1].t_ns - e.t_ns) <= std::llabs(groundtruth[j].t_ns - e.t_ns)) {
      ++j;
    }
    if (j < groundtruth.size() && std::llabs(groundtruth[j].t_ns - e.t_ns) <= kMatchToleranceNs) {
      matched.push_back(e);
      p_est.push_back(e.p_W);
      p_gt.push_back(groundtruth[j].p_W);
    }
  }
  const std::size_t n = matched.size();
  if (n < 2 || alignment == experiments::Alignment::kNone) return matched;

  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  double s = 1.0;
  Eigen::Vector3d mean_est = Eigen::Vector3d::Zero(), mean_gt = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    mean_est += p_est[i] / static_cast<double>(n);
    mean_gt += p_gt[i] / static_cast<double>(n);
  }
  if (alignment == experiments::Alignment::kPosYaw) {
    // Yaw maximizing sum of dot products of the centred horizontal positions.
    double sin_sum = 0.0, cos_sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d a = p_est[i] - mean_est, b = p_gt[i] - mean_gt;
      cos_sum += a.x() * b.x() + a.y() * b.y();
      sin_sum += a.x() * b.y() - a.y() * b.x();
    }
    R = Eigen::AngleAxisd(std::atan2(sin_sum, cos_sum), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    t = mean_gt - R * mean_est;
  } else {
    Eigen::Matrix3Xd src(3, n), dst(3, n);
    for (std::size_t i = 0; i < n; ++i) {
      src.col(i) = p_est[i];
      dst.col(i) = p_gt[i];
    }
    const Eigen::Matrix4d T = Eigen::umeyama(src, dst, alignment == experiments::Alignment::kSim3);
    s = T.block<3, 1>(0, 0).norm();
    R = T.block<3, 3>(0, 0) / s;
    t = T.block<3, 1>(0, 3);
  }
  const Eigen::Quaterniond q(R);
  for (StampedPose& pose : matched) {
    pose.p_W = s * (R * pose.p_W) + t;
    pose.q_WB = (q * pose.q_WB).normalized();
  }
  return matched;
}

}  // namespace vigil::plots
