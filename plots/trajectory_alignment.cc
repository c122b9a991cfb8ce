#include "plots/trajectory_alignment.h"

#include "evaluation/alignment.h"
#include "evaluation/association.h"

namespace vigil::plots {

Trajectory AlignForDisplay(const Trajectory& estimate, const Trajectory& groundtruth,
                           evaluation::Alignment alignment) {
  std::vector<int64_t> est_ns, gt_ns;
  for (const StampedPose& p : estimate) est_ns.push_back(p.t_ns);
  for (const StampedPose& p : groundtruth) gt_ns.push_back(p.t_ns);
  Trajectory matched;
  std::vector<Eigen::Vector3d> p_est, p_gt;
  for (const evaluation::MatchedIndices& m : evaluation::AssociateTimestamps(est_ns, gt_ns)) {
    matched.push_back(estimate[m.est]);
    p_est.push_back(estimate[m.est].p_W);
    p_gt.push_back(groundtruth[m.gt].p_W);
  }
  if (matched.empty()) return matched;
  const evaluation::SimilarityTransform T = evaluation::AlignPositions(p_est, p_gt, alignment);
  for (StampedPose& pose : matched) {
    pose.p_W = T.Apply(pose.p_W);
    pose.q_WB = T.Rotate(pose.q_WB).normalized();
  }
  return matched;
}

}  // namespace vigil::plots
