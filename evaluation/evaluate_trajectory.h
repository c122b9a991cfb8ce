// rpg-compatible evaluation of an estimated trajectory against its ground truth: association, alignment,
// absolute trajectory error (ATE) and relative errors per sub-trajectory length. The library behind
// metrics.json and `vigil eval`.
//
// ATE per matched pose after alignment: translation |p_gt - (s R p_est + t)| [m] and rotation = angle of
// (R R_est) R_gt^T [deg]. Coverage = covered ground-truth poses / ground-truth poses (coverage.h).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/types.h"
#include "evaluation/alignment.h"
#include "evaluation/association.h"
#include "evaluation/evaluation_options.h"
#include "evaluation/nees.h"
#include "evaluation/statistics.h"

namespace vigil::evaluation {

struct RelativeErrorStatistics {
  double distance_m = 0.0;
  ErrorStatistics trans_m, trans_perc, yaw_deg, rot_deg;
};

struct TrajectoryEvaluation {
  Alignment align = Alignment::kPosYaw;
  SimilarityTransform alignment;  // estimate -> ground-truth world (identity when nothing matched)
  std::size_t gt_poses = 0, est_poses = 0, matched_poses = 0;
  std::size_t covered_poses = 0;  // matched, or between estimate poses close in time (coverage.h)
  double coverage = 0.0;          // covered_poses / gt_poses (0 without ground truth)
  // Distance travelled along the matched ground truth (the poses an estimate pose was associated with).
  // rpg_trajectory_evaluation reports the length of the whole (raw) ground truth instead; the two agree when
  // coverage = 1 and this one is shorter when the estimate starts late (initialization) or stops early.
  double gt_length_m = 0.0;
  ErrorStatistics ate_trans_m, ate_rot_deg;
  // The motion the alignment rests on: the largest distance of a matched ground-truth position from their
  // centroid (horizontal for posyaw). Below options.min_alignment_extent_m the alignment is not defined
  // (alignment_defined false, never for `none`): the ATE statistics are then left empty (n = 0).
  double alignment_extent_m = 0.0;
  bool alignment_defined = true;
  // Why the errors are no result (options.min_coverage, the alignment's extent); empty when they are.
  std::string inconclusive_reason;
  // options.divergence applied: the largest ATE RMSE that is not divergence, and whether the run exceeds it
  // (false when nothing matched, or the run is inconclusive: such a run is failed or inconclusive).
  double divergence_bound_m = 0.0;
  bool diverged = false;
  std::vector<RelativeErrorStatistics> relative;  // one per options.distances_m, in that order
  // Position and orientation NEES (nees.h); set by the caller that has the pose covariances (n = 0 without).
  NeesStatistics nees;
};

// Never throws for a poor or empty estimate: with no matched pose every statistic has n = 0.
TrajectoryEvaluation EvaluateTrajectory(const Trajectory& gt, const Trajectory& est,
                                        const EvaluationOptions& options,
                                        int64_t max_difference_ns = kDefaultMaxAssociationDifferenceNs);

// {"ate": {"align", "trans_m": STATS, "rot_deg": STATS, "matched_poses", "scale", "alignment_extent_m",
// "alignment_defined"}, "relative":
// [{"distance_m", "trans_m", "trans_perc", "yaw_deg", "rot_deg"}...], "coverage": fraction, "gt_length_m":
// .., "divergence": {"bound_m", "diverged"}, "nees": {"position": STATS, "orientation": STATS}} with STATS =
// {"rmse", "mean", "median", "std", "min", "max", "n"} (n of a relative entry: its segment count); the
// metrics.json of a run directory (docs/formats.md, docs/sweeps.md).
nlohmann::json EvaluationJson(const TrajectoryEvaluation& evaluation);

// A readable multi-line table of the same numbers (for `vigil eval`).
std::string EvaluationTable(const TrajectoryEvaluation& evaluation);

}  // namespace vigil::evaluation
