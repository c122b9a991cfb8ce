// Options of the trajectory evaluation (rpg_trajectory_evaluation definitions).
#pragma once

#include <vector>

#include "core/config.h"

namespace vigil::evaluation {

enum class Alignment { kPosYaw, kSe3, kSim3, kNone };

inline const config::EnumNames<Alignment>& AlignmentNames() {
  static const config::EnumNames<Alignment> names = {{"posyaw", Alignment::kPosYaw},
                                                     {"se3", Alignment::kSe3},
                                                     {"sim3", Alignment::kSim3},
                                                     {"none", Alignment::kNone}};
  return names;
}

// The `diverged` verdict of a run: its ATE translation RMSE (after the alignment) exceeds
// length_fraction x the distance travelled along the matched ground truth + margin_m. The margin keeps a
// short run's noise from counting; the fraction scales the bound with the course (about 1 m on the paper's
// 117 m ellipse, where a working estimator stays near 0.04 m and the worst glitched runs it survives near
// 0.5 m). docs/estimator.md explains the choice.
struct DivergenceOptions {
  double length_fraction = 0.004;
  double margin_m = 0.5;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("length_fraction", length_fraction,
            "a run is diverged when its ATE RMSE exceeds this fraction of the distance travelled plus "
            "margin_m",
            Bounds::NonNegative());
    v.Field("margin_m", margin_m, "the constant part of the divergence bound [m]", Bounds::NonNegative());
  }
};

// A run's errors are a result only when they rest on enough of the run: its estimate covers at least
// min_coverage of the ground-truth poses (coverage.h: associated with an estimate pose, or between two
// estimate poses at most max_pose_gap_s apart), and the matched ground truth moves far enough for the
// alignment to be defined (the largest distance of a matched position from their centroid, horizontal for
// posyaw, at least min_alignment_extent_m; `none` needs no motion). Below either the run is `inconclusive`
// (run_metrics.h): one pose always aligns exactly, and a yaw fitted to 0.01 m of travel is arbitrary.
struct EvaluationOptions {
  Alignment align = Alignment::kPosYaw;
  std::vector<double> distances_m = {7.0, 14.0, 21.0, 28.0, 35.0};
  DivergenceOptions divergence;
  double min_coverage = 0.25;
  double max_pose_gap_s = 0.25;
  double min_alignment_extent_m = 0.5;

  template <class V>
  void Visit(V& v) {
    v.Enum("align", align, AlignmentNames(),
           "trajectory alignment before ATE: posyaw (4 DoF), se3, sim3, none");
    v.Field("distances_m", distances_m, "sub-trajectory lengths of the relative error [m]",
            config::Bounds::Positive());
    v.Section("divergence", divergence, "when a run's error makes it `diverged` rather than `ok`");
    v.Field("min_coverage", min_coverage,
            "a run whose estimate covers less than this fraction of the ground-truth poses is "
            "`inconclusive`, not `ok`",
            config::Bounds::Probability());
    v.Field("max_pose_gap_s", max_pose_gap_s,
            "a ground-truth pose between two estimate poses at most this far apart is covered, as is one "
            "associated with an estimate pose (an estimate at 10 Hz covers a 30 Hz ground truth) [s]",
            config::Bounds::NonNegative());
    v.Field("min_alignment_extent_m", min_alignment_extent_m,
            "a run whose matched ground truth spans less than this (horizontally for posyaw) from its "
            "centroid is `inconclusive`: the alignment is not defined and its ATE is not computed [m]",
            config::Bounds::NonNegative());
  }
};

}  // namespace vigil::evaluation
