// The newest pose's covariance: the window's information at the current estimate (the same factors the
// solve used, robust loss applied as Ceres does, with the anchored prior in place of the solve's), the
// feature depths eliminated by the marginalization's Schur complement, the gauge held at the run's first
// frame (pose_covariance.h).
#include <memory>
#include <utility>
#include <vector>

#include "estimator/estimator.h"
#include "estimator/imu_factor.h"

namespace vigil::estimator {

std::optional<Matrix6d> Estimator::NewestPoseCovariance() {
  if (window_.size() < 2) return std::nullopt;
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  std::vector<MarginalizationTerm> terms;
  DroppedBlocks dropped;
  if (bias_prior_) terms.push_back({bias_prior_.get(), nullptr, {window_.front()->speed_bias}});
  for (std::size_t k = 1; k < window_.size(); ++k) {
    auto factor = std::make_unique<ImuFactor>(*window_[k]->imu_from_prev, g_W_);
    terms.push_back(
        {factor.get(),
         nullptr,
         {window_[k - 1]->pose, window_[k - 1]->speed_bias, window_[k]->pose, window_[k]->speed_bias}});
    costs.push_back(std::move(factor));
  }
  std::vector<ReprojectionTerm> reprojections;
  for (auto& [id, track] : features_.tracks()) {
    if (!features_.Usable(track)) continue;
    dropped.push_back(&track.inv_depth);
    AppendReprojectionTerms(id, track, &track.inv_depth, &reprojections);
  }
  for (const ReprojectionTerm& term : reprojections)
    terms.push_back({term.factor, &loss_, {term.blocks.begin(), term.blocks.end()}});

  // The depths eliminated: what is left is the information of the window's states.
  SchurComplement states;
  if (!EliminateDropped(anchored_prior_.get(), terms, dropped,
                        options_.window.marginalization_eigen_threshold, &states))
    return std::nullopt;
  // The blocks' sizes and the first columns of the oldest and the newest pose.
  const Frame& oldest = *window_.front();
  const Frame& newest = *window_.back();
  std::vector<int> block_sizes;
  int oldest_column = -1, newest_column = -1, c = 0;
  for (const LinearPrior::Block& b : states.blocks) {
    if (b.address == oldest.pose) oldest_column = c;
    if (b.address == newest.pose) newest_column = c;
    c += b.tangent;
    block_sizes.push_back(b.tangent);
  }
  if (oldest_column < 0 || newest_column < 0) return std::nullopt;
  // Until the first frame leaves the window (or when the anchored prior was lost), it is the oldest one.
  if (!anchored_prior_) AddGaugeInformation(oldest.State().q_WB, oldest_column, &states.H);
  Matrix6d covariance;
  if (!MarginalPoseCovariance(std::move(states.H), block_sizes, newest_column, &covariance))
    return std::nullopt;
  return covariance;
}

}  // namespace vigil::estimator
