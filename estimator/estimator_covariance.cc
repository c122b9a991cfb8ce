// The newest pose's covariance: the window's information at the current estimate (the same factors the
// solve used, robust loss applied as Ceres does, with the anchored prior in place of the solve's), the
// feature depths eliminated track by track (window_information.h), the gauge held at the run's first frame
// (pose_covariance.h).
#include <memory>
#include <utility>
#include <vector>

#include "estimator/estimator.h"
#include "estimator/imu_factor.h"
#include "estimator/window_information.h"

namespace vigil::estimator {

std::optional<Matrix6d> Estimator::NewestPoseCovariance() {
  if (window_.size() < 2) return std::nullopt;
  std::vector<double*> poses, speed_biases;
  for (const auto& f : window_) {
    poses.push_back(f->pose);
    speed_biases.push_back(f->speed_bias);
  }
  WindowInformation information(std::move(poses), std::move(speed_biases));
  if (bias_prior_ && !information.AddFactor(*bias_prior_, nullptr, {window_.front()->speed_bias}))
    return std::nullopt;
  for (std::size_t k = 1; k < window_.size(); ++k) {
    const ImuFactor factor(*window_[k]->imu_from_prev, g_W_);
    if (!information.AddFactor(
            factor, nullptr,
            {window_[k - 1]->pose, window_[k - 1]->speed_bias, window_[k]->pose, window_[k]->speed_bias}))
      return std::nullopt;
  }
  // Each track's reprojections, its depth eliminated: what is left is the information of the window's states.
  std::vector<ReprojectionTerm> reprojections;
  std::vector<WindowInformation::Reprojection> track_terms;
  for (auto& [id, track] : features_.tracks()) {
    if (!features_.Usable(track)) continue;
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
  Matrix6d covariance;
  const std::vector<int> block_sizes = information.BlockSizes();
  if (!MarginalPoseCovariance(std::move(information.mutable_H()), block_sizes,
                              WindowInformation::PoseColumn(information.frames() - 1), &covariance))
    return std::nullopt;
  return covariance;
}

}  // namespace vigil::estimator
