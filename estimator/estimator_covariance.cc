// The newest pose's covariance: the window's information at the current estimate (the same factors the
// solve used, zero-velocity terms included, robust loss applied as Ceres does, with the anchored prior in
// place of the solve's), the feature depths eliminated track by track (window_information.h), the gauge held
// at the run's first frame (pose_covariance.h), its marginal from the factorization of
// window_factorization.h.
#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "estimator/estimator.h"
#include "estimator/imu_factor.h"
#include "estimator/window_factorization.h"
#include "estimator/window_information.h"

namespace vigil::estimator {

std::optional<Matrix6d> Estimator::NewestPoseCovariance(const WindowInformation* oldest) {
  if (window_.size() < 2) return std::nullopt;
  // With `oldest`, the terms over the oldest frame's blocks are its, and are not linearized again.
  const Frame& oldest_frame = *window_.front();
  const auto over_oldest = [&](const TermBlocks& blocks) {
    return oldest != nullptr && std::any_of(blocks.begin(), blocks.end(), [&](const double* block) {
             return block == oldest_frame.pose || block == oldest_frame.speed_bias;
           });
  };
  std::vector<double*> poses, speed_biases;
  for (const auto& f : window_) {
    poses.push_back(f->pose);
    speed_biases.push_back(f->speed_bias);
  }
  // The zero-velocity terms of the frames standing still: without them a window at rest, whose tracks have
  // no parallax, holds no velocity and no translation, and has no covariance.
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  std::vector<MarginalizationTerm> terms;
  AppendZeroVelocityTerms(speed_biases, &costs, &terms);
  AppendPointTerms(&costs, &terms);  // the landmark points' observations (window.oldest_tracks points)
  WindowInformation information(std::move(poses), std::move(speed_biases), PointBlocks());
  if (oldest != nullptr && !information.Add(*oldest)) return std::nullopt;
  if (bias_prior_ && oldest == nullptr &&
      !information.AddFactor(*bias_prior_, nullptr, {window_.front()->speed_bias}))
    return std::nullopt;
  for (std::size_t k = oldest != nullptr ? 2 : 1; k < window_.size(); ++k) {
    const ImuFactor factor(*window_[k]->imu_from_prev, g_W_);
    if (!information.AddFactor(
            factor, nullptr,
            {window_[k - 1]->pose, window_[k - 1]->speed_bias, window_[k]->pose, window_[k]->speed_bias}))
      return std::nullopt;
  }
  for (const MarginalizationTerm& term : terms)
    if (!over_oldest(term.blocks) && !information.AddTerm(term)) return std::nullopt;
  // Each track's reprojections, its depth eliminated: what is left is the information of the window's states.
  std::vector<ReprojectionTerm> reprojections;
  std::vector<WindowInformation::Reprojection> track_terms;
  for (auto& [id, track] : features_.tracks()) {
    if (!IsDepthTrack(id, track) || (oldest != nullptr && track.anchor_frame() == oldest_frame.id)) continue;
    reprojections.clear();
    AppendReprojectionTerms(id, track, &track.inv_depth, &reprojections);
    track_terms.clear();
    for (const ReprojectionTerm& term : reprojections) track_terms.push_back({term.factor, term.blocks});
    if (!information.AddTrack(track_terms.data(), track_terms.data() + track_terms.size(), &loss_,
                              options_.window.marginalization_eigen_threshold))
      return std::nullopt;
  }
  if (anchored_prior_) {
    if (!information.AddPrior(*anchored_prior_)) return std::nullopt;
  } else {
    // Until the first frame leaves the window (or when the anchored prior was lost), it is the oldest one.
    AddGaugeInformation(window_.front()->State().q_WB, WindowInformation::PoseColumn(0),
                        &information.mutable_H());
  }
  if (!information.H().allFinite() || !information.g().allFinite()) return std::nullopt;
  WindowFactorization factorization;
  if (!factorization.Compute(information.H(), information.points())) return std::nullopt;
  const Matrix6d covariance = factorization.NewestPoseCovariance();
  if (!covariance.allFinite()) return std::nullopt;
  return covariance;
}

}  // namespace vigil::estimator
