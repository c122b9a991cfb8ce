#include "evaluation/nees.h"

#include <cmath>

#include <Eigen/Cholesky>

#include "core/so3.h"

namespace vigil::evaluation {
namespace {

// e^T P^-1 e, or false when P is not positive definite or not finite.
bool NeesOf(const Eigen::Matrix3d& P, const Eigen::Vector3d& e, double* nees) {
  if (!P.allFinite()) return false;
  const Eigen::LLT<Eigen::Matrix3d> llt(P);
  if (llt.info() != Eigen::Success) return false;
  *nees = e.dot(llt.solve(e));
  return std::isfinite(*nees);
}

std::vector<MatchedIndices> Match(const Trajectory& gt, const Trajectory& est, int64_t max_difference_ns) {
  std::vector<int64_t> gt_ns(gt.size()), est_ns(est.size());
  for (std::size_t k = 0; k < gt.size(); ++k) gt_ns[k] = gt[k].t_ns;
  for (std::size_t k = 0; k < est.size(); ++k) est_ns[k] = est[k].t_ns;
  return AssociateTimestamps(est_ns, gt_ns, max_difference_ns);
}

}  // namespace

SimilarityTransform GaugeAlignment(const Trajectory& gt, const Trajectory& est,
                                   const std::vector<Eigen::Matrix<double, 6, 6>>& covariances,
                                   int64_t max_difference_ns) {
  SimilarityTransform out;
  if (covariances.size() != est.size()) return out;
  for (const MatchedIndices& m : Match(gt, est, max_difference_ns)) {
    if (!covariances[m.est].allFinite()) continue;
    // The yaw of R_gt R_est^T: the rotation about z closest to it.
    const Eigen::Matrix3d R =
        gt[m.gt].q_WB.toRotationMatrix() * est[m.est].q_WB.toRotationMatrix().transpose();
    const double yaw = std::atan2(R(1, 0) - R(0, 1), R(0, 0) + R(1, 1));
    out.R = RotZ(yaw);
    out.t = gt[m.gt].p_W - out.R * est[m.est].p_W;
    return out;
  }
  return out;
}

NeesStatistics ComputeNees(const Trajectory& gt, const Trajectory& est,
                           const std::vector<Eigen::Matrix<double, 6, 6>>& covariances,
                           const SimilarityTransform& est_to_gt, int64_t max_difference_ns) {
  NeesStatistics out;
  if (covariances.size() != est.size() || est.empty()) return out;
  const Eigen::Matrix3d R_T = est_to_gt.R.transpose();
  std::vector<double> position, orientation;
  for (const MatchedIndices& m : Match(gt, est, max_difference_ns)) {
    const StampedPose& e = est[m.est];
    const StampedPose& g = gt[m.gt];
    const Eigen::Vector3d p_gt_est = R_T * (g.p_W - est_to_gt.t) / est_to_gt.scale;
    const Eigen::Quaterniond q_gt_est = (Eigen::Quaterniond(R_T) * g.q_WB).normalized();
    const Eigen::Vector3d e_p = p_gt_est - e.p_W;
    const Eigen::Vector3d e_theta = LogQ((e.q_WB.conjugate() * q_gt_est).normalized());
    const Eigen::Matrix<double, 6, 6>& P = covariances[m.est];
    double nees_p = 0.0, nees_theta = 0.0;
    if (!NeesOf(P.topLeftCorner<3, 3>(), e_p, &nees_p) ||
        !NeesOf(P.bottomRightCorner<3, 3>(), e_theta, &nees_theta))
      continue;
    position.push_back(nees_p);
    orientation.push_back(nees_theta);
  }
  out.position = ComputeStatistics(position);
  out.orientation = ComputeStatistics(orientation);
  return out;
}

}  // namespace vigil::evaluation
