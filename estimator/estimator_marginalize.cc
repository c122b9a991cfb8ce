// Sliding the window: the oldest frame (after a keyframe) or the second newest frame leaves it.
#include <memory>
#include <vector>

#include "estimator/estimator.h"
#include "estimator/imu_factor.h"
#include "estimator/zero_velocity_factor.h"

namespace vigil::estimator {

void Estimator::KeepPrior(const std::vector<MarginalizationTerm>& terms, const DroppedBlocks& dropped) {
  auto prior = std::make_shared<LinearPrior>();
  if (Marginalize(prior_.get(), terms, dropped, options_.window.marginalization_eigen_threshold,
                  prior.get())) {
    prior_ = std::move(prior);
  } else {
    prior_.reset();
    ++marginalization_failures_;
  }
}

void Estimator::KeepAnchoredPrior(const std::vector<MarginalizationTerm>& terms,
                                  const DroppedBlocks& dropped) {
  const LinearPrior gauge = GaugePrior(window_.front()->pose);
  const LinearPrior* previous = anchored_prior_ ? anchored_prior_.get() : &gauge;
  auto anchored = std::make_shared<LinearPrior>();
  // Only the pose covariance reads it, as information: no square-root form.
  if (MarginalizeInformation(previous, terms, dropped, options_.window.marginalization_eigen_threshold,
                             anchored.get()))
    anchored_prior_ = std::move(anchored);
  else
    anchored_prior_.reset();
}

void Estimator::AppendOldestZeroVelocityTerms(std::vector<std::unique_ptr<ceres::CostFunction>>* costs,
                                              std::vector<MarginalizationTerm>* terms) {
  if (!ZeroVelocityActive() || window_.size() < 2 || !window_[1]->stationary) return;
  const ZeroVelocityOptions& o = options_.zero_velocity;
  Frame& oldest = *window_[0];
  Frame& second = *window_[1];
  auto velocity = std::make_unique<ZeroVelocityFactor>(o.velocity_std_mps);
  terms->push_back({velocity.get(), nullptr, {oldest.speed_bias}});
  costs->push_back(std::move(velocity));
  auto motion = std::make_unique<NoMotionFactor>(o.position_std_m, o.rotation_std_rad);
  terms->push_back({motion.get(), nullptr, {oldest.pose, second.pose}});
  costs->push_back(std::move(motion));
}

Estimator::OldestFrameTerms Estimator::TermsOfOldest() {
  OldestFrameTerms out;
  Frame& oldest = *window_.front();
  Frame& second = *window_[1];
  out.dropped = {oldest.pose, oldest.speed_bias};
  if (bias_prior_) out.terms.push_back({bias_prior_.get(), nullptr, {oldest.speed_bias}});
  auto factor = std::make_unique<ImuFactor>(*second.imu_from_prev, g_W_);
  out.terms.push_back(
      {factor.get(), nullptr, {oldest.pose, oldest.speed_bias, second.pose, second.speed_bias}});
  out.costs.push_back(std::move(factor));
  AppendOldestZeroVelocityTerms(&out.costs, &out.terms);
  std::vector<ReprojectionTerm> reprojections;
  for (auto& [id, track] : features_.tracks()) {
    if (!features_.Usable(track) || track.anchor_frame() != oldest.id) continue;
    out.dropped.push_back(&track.inv_depth);
    AppendReprojectionTerms(id, track, &track.inv_depth, &reprojections);
    out.tracks.push_back(id);
  }
  for (const ReprojectionTerm& term : reprojections)
    out.terms.push_back({term.factor, &loss_, {term.blocks.begin(), term.blocks.end()}});
  return out;
}

void Estimator::MarginalizeOldest(bool with_prior) {
  Frame& oldest = *window_.front();
  std::vector<int> restarted;  // tracks whose observations all went into the prior
  if (with_prior && window_.size() >= 2) {
    const OldestFrameTerms oldest_terms = TermsOfOldest();
    KeepPrior(oldest_terms.terms, oldest_terms.dropped);
    if (options_.pose_covariance) KeepAnchoredPrior(oldest_terms.terms, oldest_terms.dropped);
    if (options_.window.oldest_tracks == OldestTracks::kRestart) restarted = oldest_terms.tracks;
  }
  bias_prior_.reset();  // the oldest frame's bias prior is now part of prior_
  for (const int id : restarted) features_.EraseTrack(id);
  features_.RemoveFrame(oldest.id, CameraPoses());
  window_.pop_front();
  window_.front()->imu_from_prev.reset();  // the oldest frame has no IMU factor
}

void Estimator::MarginalizeSecondNewest(bool with_prior) {
  const std::size_t n = window_.size();
  Frame& second_newest = *window_[n - 2];
  Frame& newest = *window_[n - 1];
  if (with_prior && prior_ &&
      (prior_->Involves(second_newest.pose) || prior_->Involves(second_newest.speed_bias))) {
    KeepPrior({}, {second_newest.pose, second_newest.speed_bias});
  }
  if (with_prior && anchored_prior_ &&
      (anchored_prior_->Involves(second_newest.pose) || anchored_prior_->Involves(second_newest.speed_bias)))
    KeepAnchoredPrior({}, {second_newest.pose, second_newest.speed_bias});
  // The newest frame's interval now starts at the frame before the dropped one: still when both were.
  newest.stationary = newest.stationary && second_newest.stationary;
  // The newest frame's IMU now starts at the frame before the dropped one.
  if (second_newest.imu_from_prev) {
    Preintegration merged = *second_newest.imu_from_prev;
    for (const Preintegration::Step& s : newest.imu_from_prev->steps())
      merged.Push(s.dt_s, s.a_B, s.w_B, s.variance_scale);
    newest.imu_from_prev = std::move(merged);
  } else {
    newest.imu_from_prev.reset();
  }
  features_.RemoveFrame(second_newest.id, CameraPoses());
  window_.erase(window_.end() - 2);
}

}  // namespace vigil::estimator
