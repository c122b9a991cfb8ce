// Sliding the window: the oldest frame (after a keyframe) or the second newest frame leaves it.
#include <memory>
#include <utility>
#include <vector>

#include "estimator/estimator.h"
#include "estimator/imu_factor.h"
#include "estimator/zero_velocity_factor.h"

namespace vigil::estimator {

void Estimator::KeepPrior(const PriorUpdate& update) {
  auto prior = std::make_shared<LinearPrior>();
  if (update(prior_.get(), PriorForm::kSquareRoot, prior.get())) {
    prior_ = std::move(prior);
  } else {
    prior_.reset();
    ++marginalization_failures_;
  }
}

void Estimator::KeepAnchoredPrior(const PriorUpdate& update) {
  const LinearPrior gauge = GaugePrior(window_.front()->pose);
  const LinearPrior* previous = anchored_prior_ ? anchored_prior_.get() : &gauge;
  auto anchored = std::make_shared<LinearPrior>();
  // Only the pose covariance reads it, as information: no square-root form.
  if (update(previous, PriorForm::kInformation, anchored.get()))
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
  OldestFrame& frame = out.frame;
  for (const auto& f : window_) {
    frame.poses.push_back(f->pose);
    frame.speed_biases.push_back(f->speed_bias);
  }
  Frame& oldest = *window_.front();
  Frame& second = *window_[1];
  if (bias_prior_) frame.factors.push_back({bias_prior_.get(), nullptr, {oldest.speed_bias}});
  auto factor = std::make_unique<ImuFactor>(*second.imu_from_prev, g_W_);
  frame.factors.push_back(
      {factor.get(), nullptr, {oldest.pose, oldest.speed_bias, second.pose, second.speed_bias}});
  out.costs.push_back(std::move(factor));
  AppendOldestZeroVelocityTerms(&out.costs, &frame.factors);
  if (PointsOn()) {
    frame.points = PointBlocks();
    frame.dropped_points = LostPoints();
    AppendPointTerms(&out.costs, &frame.factors, oldest.id);
  }
  std::vector<ReprojectionTerm> reprojections;
  for (auto& [id, track] : features_.tracks()) {
    if (!IsDepthTrack(id, track) || track.anchor_frame() != oldest.id) continue;
    reprojections.clear();
    AppendReprojectionTerms(id, track, &track.inv_depth, &reprojections);
    std::vector<WindowInformation::Reprojection>& terms = frame.tracks.emplace_back();
    for (const ReprojectionTerm& term : reprojections) terms.push_back({term.factor, term.blocks});
    out.tracks.push_back(id);
  }
  frame.reprojection_loss = &loss_;
  return out;
}

Estimator::LinearizedOldest::LinearizedOldest(Estimator& estimator)
    : terms(estimator.TermsOfOldest()),
      marginalization(terms.frame, estimator.options_.window.marginalization_eigen_threshold) {}

void Estimator::MarginalizeOldest(const LinearizedOldest* linearized) {
  Frame& oldest = *window_.front();
  std::vector<int> restarted;  // tracks whose observations all went into the prior
  if (linearized) {
    const PriorUpdate update = [&](const LinearPrior* previous, PriorForm form, LinearPrior* prior) {
      return linearized->marginalization.Prior(previous, form, prior);
    };
    KeepPrior(update);
    if (options_.pose_covariance) KeepAnchoredPrior(update);
    if (options_.window.oldest_tracks == OldestTracks::kRestart) restarted = linearized->terms.tracks;
  }
  bias_prior_.reset();  // the oldest frame's bias prior is now part of prior_
  for (const int id : restarted) features_.EraseTrack(id);
  if (linearized) ErasePoints(linearized->terms.frame.dropped_points);
  features_.RemoveFrame(oldest.id, CameraPoses());
  window_.pop_front();
  window_.front()->imu_from_prev.reset();  // the oldest frame has no IMU factor
}

void Estimator::MarginalizeSecondNewest(bool with_prior) {
  const std::size_t n = window_.size();
  Frame& second_newest = *window_[n - 2];
  Frame& newest = *window_[n - 1];
  // Only a prior is over its states: they are eliminated from it.
  const PriorUpdate update = [&](const LinearPrior* previous, PriorForm form, LinearPrior* prior) {
    SchurComplement schur;
    return EliminateDropped(previous, {}, {second_newest.pose, second_newest.speed_bias},
                            options_.window.marginalization_eigen_threshold, &schur) &&
           PriorOfSchurComplement(std::move(schur), options_.window.marginalization_eigen_threshold, form,
                                  prior);
  };
  if (with_prior && prior_ &&
      (prior_->Involves(second_newest.pose) || prior_->Involves(second_newest.speed_bias)))
    KeepPrior(update);
  if (with_prior && anchored_prior_ &&
      (anchored_prior_->Involves(second_newest.pose) || anchored_prior_->Involves(second_newest.speed_bias)))
    KeepAnchoredPrior(update);
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
