#include "estimator/oldest_frame_marginalization.h"

#include <algorithm>
#include <utility>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {
namespace {

// The kept blocks in EliminateDropped's order: the previous prior's, then the terms' in order of appearance,
// each once, without the oldest frame's and the dropped points.
std::vector<double*> KeptBlocks(const LinearPrior* previous, const OldestFrame& oldest) {
  std::vector<double*> kept;
  auto keep = [&](double* block) {
    if (block == oldest.poses.front() || block == oldest.speed_biases.front()) return;
    if (std::find(oldest.dropped_points.begin(), oldest.dropped_points.end(), block) !=
        oldest.dropped_points.end())
      return;
    if (std::find(kept.begin(), kept.end(), block) == kept.end()) kept.push_back(block);
  };
  if (previous != nullptr)
    for (const LinearPrior::Block& b : previous->blocks) keep(b.address);
  for (const MarginalizationTerm& term : oldest.factors)
    for (double* block : term.blocks) keep(block);
  for (const auto& track : oldest.tracks)
    for (const WindowInformation::Reprojection& t : track) {
      keep(t.blocks[0]);
      keep(t.blocks[1]);
    }
  return kept;
}

// A kept block as a prior's block, at its current value; `tangent` as WindowInformation::ColumnOf gives it.
LinearPrior::Block PriorBlock(double* block, int tangent) {
  const int size = tangent == kPoseTangentSize ? kPoseSize : tangent;
  return {block, size, tangent, std::vector<double>(block, block + size)};
}

}  // namespace

OldestFrameMarginalization::OldestFrameMarginalization(const OldestFrame& oldest, double eigen_threshold)
    : oldest_(oldest),
      eigen_threshold_(eigen_threshold),
      information_(oldest.poses, oldest.speed_biases, oldest.points) {
  if (oldest.poses.empty() || oldest.poses.size() != oldest.speed_biases.size()) return;
  for (const MarginalizationTerm& term : oldest.factors)
    if (!information_.AddTerm(term)) return;
  for (const auto& track : oldest.tracks)
    if (!information_.AddTrack(track.data(), track.data() + track.size(), oldest.reprojection_loss,
                               eigen_threshold))
      return;
  linearized_ = true;
}

bool OldestFrameMarginalization::Prior(const LinearPrior* previous, PriorForm form,
                                       LinearPrior* prior) const {
  if (!linearized_) return false;
  // The dropped columns first (the oldest frame's pose and speed-bias: window columns 0-14, then the dropped
  // points'), then the kept blocks'.
  std::vector<int> columns(WindowInformation::kFrameSize);
  for (int i = 0; i < WindowInformation::kFrameSize; ++i) columns[i] = i;
  // Where each block's columns start among `columns`: the dropped ones', then each kept block's.
  std::vector<std::pair<const double*, int>> first_column = {
      {oldest_.poses.front(), WindowInformation::PoseColumn(0)},
      {oldest_.speed_biases.front(), WindowInformation::SpeedBiasColumn(0)}};
  for (const double* point : oldest_.dropped_points) {
    const WindowInformation::BlockColumn window = information_.ColumnOf(point);
    if (window.column < 0) return false;
    first_column.emplace_back(point, static_cast<int>(columns.size()));
    for (int i = 0; i < window.tangent; ++i) columns.push_back(window.column + i);
  }
  const int dropped = static_cast<int>(columns.size());
  SchurComplement schur;
  for (double* block : KeptBlocks(previous, oldest_)) {
    const WindowInformation::BlockColumn window = information_.ColumnOf(block);
    if (window.column < 0) return false;
    first_column.emplace_back(block, static_cast<int>(columns.size()));
    for (int i = 0; i < window.tangent; ++i) columns.push_back(window.column + i);
    schur.blocks.push_back(PriorBlock(block, window.tangent));
  }
  if (schur.blocks.empty()) return false;
  Eigen::MatrixXd H = information_.H()(columns, columns);
  Eigen::VectorXd g = information_.g()(columns);
  if (previous != nullptr) {
    // The previous prior at the current values, each of its blocks at its place among those columns (every
    // one of them is the oldest frame's or kept).
    Eigen::MatrixXd H_prior;
    Eigen::VectorXd g_prior;
    PriorInformationAtCurrentValues(*previous, &H_prior, &g_prior);
    std::vector<int> at;  // the prior's columns among `columns`
    for (const LinearPrior::Block& b : previous->blocks) {
      const auto it = std::find_if(first_column.begin(), first_column.end(),
                                   [&](const auto& entry) { return entry.first == b.address; });
      for (int i = 0; i < b.tangent; ++i) at.push_back(it->second + i);
    }
    H(at, at) += H_prior;
    g(at) += g_prior;
  }
  EliminateLeading(&H, &g, dropped, eigen_threshold_, &schur.H, &schur.g);
  if (!schur.H.allFinite() || !schur.g.allFinite()) return false;
  return PriorOfSchurComplement(std::move(schur), eigen_threshold_, form, prior);
}

bool MarginalizeOldestFrame(const LinearPrior* previous, const OldestFrame& oldest, double eigen_threshold,
                            PriorForm form, LinearPrior* prior) {
  return OldestFrameMarginalization(oldest, eigen_threshold).Prior(previous, form, prior);
}

std::vector<MarginalizationTerm> GeneralTerms(const OldestFrame& oldest) {
  std::vector<MarginalizationTerm> terms = oldest.factors;
  for (const auto& track : oldest.tracks)
    for (const WindowInformation::Reprojection& t : track)
      terms.push_back({t.factor, oldest.reprojection_loss, {t.blocks.begin(), t.blocks.end()}});
  return terms;
}

DroppedBlocks GeneralDroppedBlocks(const OldestFrame& oldest) {
  DroppedBlocks dropped = {oldest.poses.front(), oldest.speed_biases.front()};
  dropped.insert(dropped.end(), oldest.dropped_points.begin(), oldest.dropped_points.end());
  for (const auto& track : oldest.tracks)
    if (!track.empty()) dropped.push_back(track.front().blocks[2]);
  return dropped;
}

}  // namespace vigil::estimator
