// The marginalization of the window's oldest frame, in the window's fixed layout.
//
// When the oldest frame leaves the window, its pose and speed-bias and the inverse depths of the tracks
// anchored in it are eliminated from the factors that involve them (its IMU factor, bias prior and
// zero-velocity factors, those tracks' reprojections) and from the previous prior. EliminateDropped
// (marginalization.h) does that for any factors, through index maps and a sparse row per depth. Here the
// structure is known: WindowInformation builds the same information (each track's reprojections in fixed
// sizes, its depth eliminated track by track, with the same pivot threshold), and the frame's 15 columns are
// eliminated from the blocks the terms involve. The prior has the same blocks in the same order as
// EliminateDropped's (the previous prior's, then the terms' in order of appearance) and the same numbers to
// rounding.
#pragma once

#include <vector>

#include <ceres/loss_function.h>

#include "estimator/marginalization.h"
#include "estimator/window_information.h"

namespace vigil::estimator {

struct OldestFrame {
  // The window's frames' blocks, the oldest (the one that leaves) first.
  std::vector<double*> poses;
  std::vector<double*> speed_biases;
  // The window's landmark points (window.oldest_tracks points; WindowInformation's layout), and those among
  // them that leave with the oldest frame (their tracks ended: only the prior holds them).
  std::vector<double*> points;
  std::vector<const double*> dropped_points;
  // The factors other than reprojections that involve the oldest frame, over window blocks (its
  // observations of points included).
  std::vector<MarginalizationTerm> factors;
  // The tracks anchored in the oldest frame: each one's reprojections, all over its inverse depth.
  std::vector<std::vector<WindowInformation::Reprojection>> tracks;
  const ceres::LossFunction* reprojection_loss = nullptr;  // may be null
};

// The oldest frame's terms linearized once, at the blocks' current values; the prior from any previous prior
// (the estimator keeps two: its own and the pose covariance's anchored one).
class OldestFrameMarginalization {
 public:
  // `oldest` must outlive this object.
  OldestFrameMarginalization(const OldestFrame& oldest, double eigen_threshold);
  // The prior that eliminating the oldest frame and its tracks' depths from `previous` (may be null) and the
  // terms leaves, in `form`. False when a factor failed, a block is not the window's, nothing is left to
  // keep, or the numbers are not finite.
  bool Prior(const LinearPrior* previous, PriorForm form, LinearPrior* prior) const;
  // The oldest frame's terms' information in the window's layout (the depths of its tracks eliminated);
  // null when a term failed.
  const WindowInformation* information() const { return linearized_ ? &information_ : nullptr; }

 private:
  const OldestFrame& oldest_;
  double eigen_threshold_;
  WindowInformation information_;
  bool linearized_ = false;
};

// OldestFrameMarginalization(oldest, eigen_threshold).Prior(previous, form, prior).
bool MarginalizeOldestFrame(const LinearPrior* previous, const OldestFrame& oldest, double eigen_threshold,
                            PriorForm form, LinearPrior* prior);

// The same marginalization for EliminateDropped: the factors, then every reprojection with the loss; the
// oldest frame's blocks, the dropped points and the tracks' depths.
std::vector<MarginalizationTerm> GeneralTerms(const OldestFrame& oldest);
DroppedBlocks GeneralDroppedBlocks(const OldestFrame& oldest);

}  // namespace vigil::estimator
