#include "evaluation/evaluate_trajectory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/config.h"
#include "core/format.h"
#include "core/so3.h"
#include "core/types.h"
#include "evaluation/coverage.h"
#include "evaluation/relative_error.h"

namespace vigil::evaluation {
namespace {

Eigen::Isometry3d Pose(const Eigen::Quaterniond& q, const Eigen::Vector3d& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = p;
  return T;
}

std::string AlignmentName(Alignment align) { return config::EnumNameOf(align, AlignmentNames()); }

// The largest distance of a position from their centroid; horizontal (x, y of W) when only yaw is fitted.
double ExtentOf(const std::vector<Eigen::Vector3d>& p, bool horizontal) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& x : p) centroid += x;
  centroid /= static_cast<double>(p.size());
  double extent = 0.0;
  for (const Eigen::Vector3d& x : p) {
    Eigen::Vector3d d = x - centroid;
    if (horizontal) d.z() = 0.0;
    extent = std::max(extent, d.norm());
  }
  return extent;
}

// Why the run's errors are no result (EvaluationOptions::min_coverage, min_alignment_extent_m), or "".
std::string InconclusiveReason(const TrajectoryEvaluation& ev, const EvaluationOptions& options) {
  if (ev.coverage < options.min_coverage)
    return "coverage " + FormatFixed(100.0 * ev.coverage, 1) + " % (" + std::to_string(ev.covered_poses) +
           " of " + std::to_string(ev.gt_poses) + " ground-truth poses) is below evaluation.min_coverage " +
           FormatFixed(100.0 * options.min_coverage, 1) + " %";
  if (!ev.alignment_defined)
    return "the matched ground truth spans " + FormatFixed(ev.alignment_extent_m, 3) +
           " m, below evaluation.min_alignment_extent_m " + FormatDouble(options.min_alignment_extent_m) +
           " m: too little motion to define the " + AlignmentName(ev.align) +
           " alignment, so its ATE is not computed (evaluation.align none needs no motion)";
  return "";
}

}  // namespace

TrajectoryEvaluation EvaluateTrajectory(const Trajectory& gt, const Trajectory& est,
                                        const EvaluationOptions& options, int64_t max_difference_ns) {
  TrajectoryEvaluation ev;
  ev.align = options.align;
  ev.gt_poses = gt.size();
  ev.est_poses = est.size();
  std::vector<int64_t> gt_ns(gt.size()), est_ns(est.size());
  for (std::size_t k = 0; k < gt.size(); ++k) gt_ns[k] = gt[k].t_ns;
  for (std::size_t k = 0; k < est.size(); ++k) est_ns[k] = est[k].t_ns;
  const std::vector<MatchedIndices> matches = AssociateTimestamps(est_ns, gt_ns, max_difference_ns);
  ev.matched_poses = matches.size();
  ev.covered_poses = CoveredPoses(est_ns, gt_ns, matches, SToNs(options.max_pose_gap_s));
  ev.coverage = gt.empty() ? 0.0 : static_cast<double>(ev.covered_poses) / static_cast<double>(gt.size());
  for (double d : options.distances_m) ev.relative.push_back({d, {}, {}, {}, {}});
  if (matches.empty()) return ev;

  std::vector<Eigen::Vector3d> p_est, p_gt;
  std::vector<Eigen::Isometry3d> T_est, T_gt;
  for (const MatchedIndices& m : matches) {
    p_est.push_back(est[m.est].p_W);
    p_gt.push_back(gt[m.gt].p_W);
    T_est.push_back(Pose(est[m.est].q_WB, est[m.est].p_W));
    T_gt.push_back(Pose(gt[m.gt].q_WB, gt[m.gt].p_W));
  }
  ev.gt_length_m = DistanceFromStart(p_gt).back();
  ev.alignment_extent_m = ExtentOf(p_gt, options.align == Alignment::kPosYaw);
  ev.alignment_defined =
      options.align == Alignment::kNone || ev.alignment_extent_m >= options.min_alignment_extent_m;
  ev.inconclusive_reason = InconclusiveReason(ev, options);
  ev.divergence_bound_m = options.divergence.length_fraction * ev.gt_length_m + options.divergence.margin_m;

  if (ev.alignment_defined) {
    ev.alignment = AlignPositions(p_est, p_gt, options.align);
    std::vector<double> e_trans, e_rot;
    for (std::size_t k = 0; k < matches.size(); ++k) {
      e_trans.push_back((p_gt[k] - ev.alignment.Apply(p_est[k])).norm());
      const Eigen::Matrix3d R_err = ev.alignment.R * T_est[k].linear() * T_gt[k].linear().transpose();
      e_rot.push_back(AngleOf(Eigen::Quaterniond(R_err)) * 180.0 / M_PI);
    }
    ev.ate_trans_m = ComputeStatistics(e_trans);
    ev.ate_rot_deg = ComputeStatistics(e_rot);
    ev.diverged = ev.inconclusive_reason.empty() && ev.ate_trans_m.rmse > ev.divergence_bound_m;
  }

  for (RelativeErrorStatistics& rel : ev.relative) {
    const RelativeErrors r = ComputeRelativeErrors(T_est, T_gt, rel.distance_m, ev.alignment.scale);
    rel.trans_m = ComputeStatistics(r.trans_m);
    rel.trans_perc = ComputeStatistics(r.trans_perc);
    rel.yaw_deg = ComputeStatistics(r.yaw_deg);
    rel.rot_deg = ComputeStatistics(r.rot_deg);
  }
  return ev;
}

nlohmann::json EvaluationJson(const TrajectoryEvaluation& ev) {
  nlohmann::json json;
  json["ate"] = {{"align", AlignmentName(ev.align)},
                 {"trans_m", StatisticsJson(ev.ate_trans_m)},
                 {"rot_deg", StatisticsJson(ev.ate_rot_deg)},
                 {"matched_poses", ev.matched_poses},
                 {"scale", ev.alignment.scale},
                 {"alignment_extent_m", ev.alignment_extent_m},
                 {"alignment_defined", ev.alignment_defined}};
  json["relative"] = nlohmann::json::array();
  for (const RelativeErrorStatistics& rel : ev.relative)
    json["relative"].push_back({{"distance_m", rel.distance_m},
                                {"trans_m", StatisticsJson(rel.trans_m)},
                                {"trans_perc", StatisticsJson(rel.trans_perc)},
                                {"yaw_deg", StatisticsJson(rel.yaw_deg)},
                                {"rot_deg", StatisticsJson(rel.rot_deg)}});
  json["coverage"] = ev.coverage;
  json["gt_length_m"] = ev.gt_length_m;
  json["divergence"] = {{"bound_m", ev.divergence_bound_m}, {"diverged", ev.diverged}};
  json["nees"] = {{"position", StatisticsJson(ev.nees.position)},
                  {"orientation", StatisticsJson(ev.nees.orientation)}};
  return json;
}

std::string EvaluationTable(const TrajectoryEvaluation& ev) {
  std::string out;
  char line[256];
  std::snprintf(
      line, sizeof(line),
      "matched %zu of %zu ground-truth poses (%zu covered, coverage %.1f %%; %zu estimate poses), length "
      "%.2f m, alignment %s (scale %.4f)\n\n",
      ev.matched_poses, ev.gt_poses, ev.covered_poses, 100.0 * ev.coverage, ev.est_poses, ev.gt_length_m,
      AlignmentName(ev.align).c_str(), ev.alignment.scale);
  out += line;
  if (!ev.inconclusive_reason.empty()) out += "inconclusive: " + ev.inconclusive_reason + "\n\n";
  const auto row = [&](const char* name, const ErrorStatistics& s) {
    std::snprintf(line, sizeof(line), "%-26s %10.4f %10.4f %10.4f %10.4f %10.4f %10.4f %7lld\n", name, s.rmse,
                  s.mean, s.median, s.std, s.min, s.max, static_cast<long long>(s.n));
    out += line;
  };
  std::snprintf(line, sizeof(line), "%-26s %10s %10s %10s %10s %10s %10s %7s\n", "error", "rmse", "mean",
                "median", "std", "min", "max", "n");
  out += line;
  row("ATE translation [m]", ev.ate_trans_m);
  row("ATE rotation [deg]", ev.ate_rot_deg);
  for (const RelativeErrorStatistics& rel : ev.relative) {
    char name[64];
    std::snprintf(name, sizeof(name), "RE %g m translation [m]", rel.distance_m);
    row(name, rel.trans_m);
    std::snprintf(name, sizeof(name), "RE %g m translation [%%]", rel.distance_m);
    row(name, rel.trans_perc);
    std::snprintf(name, sizeof(name), "RE %g m yaw [deg]", rel.distance_m);
    row(name, rel.yaw_deg);
    std::snprintf(name, sizeof(name), "RE %g m rotation [deg]", rel.distance_m);
    row(name, rel.rot_deg);
  }
  return out;
}

}  // namespace vigil::evaluation
