#include "estimator/oldest_frame_marginalization.h"

#include <algorithm>
#include <utility>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {
namespace {

// The kept blocks in EliminateDropped's order: the previous prior's, then the terms' in order of appearance,
// each once, without the oldest frame's.
std::vector<double*> KeptBlocks(const LinearPrior* previous, const OldestFrame& oldest) {
  std::vector<double*> kept;
  auto keep = [&](double* block) {
    if (block == oldest.poses.front() || block == oldest.speed_biases.front()) return;
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

// The window columns of a frame's block, as a LinearPrior block at its current value; false when the block is
// not the window's.
bool AsPriorBlock(const OldestFrame& oldest, double* block, int* column, LinearPrior::Block* out) {
  for (int k = 0; k < static_cast<int>(oldest.poses.size()); ++k) {
    const bool pose = oldest.poses[k] == block;
    if (!pose && oldest.speed_biases[k] != block) continue;
    const int size = pose ? kPoseSize : kSpeedBiasSize;
    *column = pose ? WindowInformation::PoseColumn(k) : WindowInformation::SpeedBiasColumn(k);
    *out = {block, size, TangentSizeOf(size), std::vector<double>(block, block + size)};
    return true;
  }
  return false;
}

}  // namespace

OldestFrameMarginalization::OldestFrameMarginalization(const OldestFrame& oldest, double eigen_threshold)
    : oldest_(oldest), eigen_threshold_(eigen_threshold), information_(oldest.poses, oldest.speed_biases) {
  if (oldest.poses.empty() || oldest.poses.size() != oldest.speed_biases.size()) return;
  for (const MarginalizationTerm& term : oldest.factors)
    if (!information_.AddFactor(*term.cost, term.loss, {term.blocks.begin(), term.blocks.end()})) return;
  for (const auto& track : oldest.tracks)
    if (!information_.AddTrack(track.data(), track.data() + track.size(), oldest.reprojection_loss,
                               eigen_threshold))
      return;
  linearized_ = true;
}

bool OldestFrameMarginalization::Prior(const LinearPrior* previous, PriorForm form,
                                       LinearPrior* prior) const {
  if (!linearized_) return false;
  // The oldest frame's columns first (its pose and speed-bias: window columns 0-14), then the kept blocks'.
  constexpr int kDropped = WindowInformation::kFrameSize;
  std::vector<int> columns(kDropped);
  for (int i = 0; i < kDropped; ++i) columns[i] = i;
  SchurComplement schur;
  for (double* block : KeptBlocks(previous, oldest_)) {
    int column = 0;
    if (!AsPriorBlock(oldest_, block, &column, &schur.blocks.emplace_back())) return false;
    for (int i = 0; i < schur.blocks.back().tangent; ++i) columns.push_back(column + i);
  }
  if (schur.blocks.empty()) return false;
  Eigen::MatrixXd H = information_.H()(columns, columns);
  Eigen::VectorXd g = information_.g()(columns);
  if (previous != nullptr) {
    // The previous prior at the current values, each of its blocks at its place among those columns.
    Eigen::MatrixXd H_prior;
    Eigen::VectorXd g_prior;
    PriorInformationAtCurrentValues(*previous, &H_prior, &g_prior);
    std::vector<int> at;  // the prior's columns among `columns`
    for (const LinearPrior::Block& b : previous->blocks) {
      int column = 0;
      LinearPrior::Block unused;
      if (!AsPriorBlock(oldest_, b.address, &column, &unused)) return false;
      const int first = static_cast<int>(std::find(columns.begin(), columns.end(), column) - columns.begin());
      for (int i = 0; i < b.tangent; ++i) at.push_back(first + i);
    }
    H(at, at) += H_prior;
    g(at) += g_prior;
  }
  EliminateLeading(&H, &g, kDropped, eigen_threshold_, &schur.H, &schur.g);
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
  for (const auto& track : oldest.tracks)
    if (!track.empty()) dropped.push_back(track.front().blocks[2]);
  return dropped;
}

}  // namespace vigil::estimator
