// The stages of one estimator frame, callable again and again on a fixed window: the window solve, the
// newest pose's covariance and the oldest frame's marginalization (its prior, without sliding the window).
// Solve() starts every time from the window's states and depths as they were when this object was made.
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "estimator/estimator.h"

namespace vigil::estimator {

class EstimatorStages {
 public:
  explicit EstimatorStages(Estimator* estimator) : e_(*estimator) {
    for (const auto& f : e_.window_) {
      std::copy_n(f->pose, kPoseSize, poses_.emplace_back().begin());
      std::copy_n(f->speed_bias, kSpeedBiasSize, speed_biases_.emplace_back().begin());
    }
    for (const auto& [id, track] : e_.features_.tracks()) depths_[id] = {track.inv_depth, track.has_depth};
    points_W_ = e_.points_W_;
  }

  int window_frames() const { return static_cast<int>(e_.window_.size()); }
  int64_t oldest_frame_ns() const { return e_.window_.front()->t_ns; }
  int usable_tracks() const {
    int n = 0;
    for (const auto& [id, track] : e_.features_.tracks()) n += e_.features_.Usable(track);
    return n;
  }

  // The landmark points (window.oldest_tracks points).
  int points() const { return static_cast<int>(e_.points_W_.size()); }
  // Whether each point's track is live, and every block of the estimator's priors is a window frame's or a
  // point's.
  bool PointsAndPriorsAreLive() const {
    for (const auto& [id, p_W] : e_.points_W_)
      if (e_.features_.tracks().count(id) == 0) return false;
    std::set<const double*> live;
    for (const auto& f : e_.window_) live.insert({f->pose, f->speed_bias});
    for (const auto& [id, p_W] : e_.points_W_) live.insert(p_W.data());
    for (const LinearPrior* prior : {e_.prior_.get(), e_.anchored_prior_.get()})
      if (prior)
        for (const LinearPrior::Block& b : prior->blocks)
          if (live.count(b.address) == 0) return false;
    return true;
  }
  // The points as saved (Solve starts from them), and their current values, by track id.
  const std::map<int, std::array<double, kPointSize>>& saved_points_W() const { return points_W_; }
  const std::map<int, std::array<double, kPointSize>>& points_W() const { return e_.points_W_; }
  // The newest frame's pose block (kPoseSize doubles).
  std::array<double, kPoseSize> NewestPose() const {
    std::array<double, kPoseSize> pose;
    std::copy_n(e_.window_.back()->pose, kPoseSize, pose.begin());
    return pose;
  }

  // The window's solve by `backend` from the saved states; false when the solver fails.
  bool Solve(SolverBackend backend) {
    Restore();
    std::string reason;
    return backend == SolverBackend::kDense ? e_.OptimizeDense(/*marginalize_oldest_next=*/true, &reason)
                                            : e_.Optimize(/*marginalize_oldest_next=*/true, &reason);
  }
  std::optional<Matrix6d> Covariance() { return e_.NewestPoseCovariance(); }
  // After a keyframe, before the oldest frame leaves: the newest pose's covariance and the prior that
  // marginalizing the oldest frame keeps, the oldest frame's terms linearized once for both (`shared`, as
  // the estimator does: Estimator::LinearizedOldest) or again for the covariance. The covariance; empty
  // when it or the marginalization fails.
  std::optional<Matrix6d> CovarianceAndMarginalize(bool shared) {
    const Estimator::LinearizedOldest oldest(e_);
    std::optional<Matrix6d> covariance =
        e_.NewestPoseCovariance(shared ? oldest.marginalization.information() : nullptr);
    LinearPrior prior;
    if (!oldest.marginalization.Prior(e_.prior_.get(), PriorForm::kSquareRoot, &prior)) return std::nullopt;
    return covariance;
  }
  // The prior that marginalizing the oldest frame would keep, as the estimator builds it (in the window's
  // layout) or by the general elimination; false when it fails.
  bool MarginalizeOldest(bool general) {
    const Estimator::OldestFrameTerms terms = e_.TermsOfOldest();
    const double threshold = e_.options_.window.marginalization_eigen_threshold;
    LinearPrior prior;
    if (general)
      return Marginalize(e_.prior_.get(), GeneralTerms(terms.frame), GeneralDroppedBlocks(terms.frame),
                         threshold, &prior);
    return MarginalizeOldestFrame(e_.prior_.get(), terms.frame, threshold, PriorForm::kSquareRoot, &prior);
  }

  // Moves the saved newest position and every saved point (the states Solve starts from).
  void OffsetSaved(const Eigen::Vector3d& newest_position_m, const Eigen::Vector3d& points_m) {
    for (int i = 0; i < 3; ++i) poses_.back()[i] += newest_position_m[i];
    for (auto& [id, p_W] : points_W_)
      for (int i = 0; i < 3; ++i) p_W[i] += points_m[i];
  }
  // The window's states, points and depths as they were when this object was made.
  void Restore() {
    for (std::size_t k = 0; k < e_.window_.size(); ++k) {
      std::copy(poses_[k].begin(), poses_[k].end(), e_.window_[k]->pose);
      std::copy(speed_biases_[k].begin(), speed_biases_[k].end(), e_.window_[k]->speed_bias);
    }
    for (auto& [id, track] : e_.features_.tracks())
      std::tie(track.inv_depth, track.has_depth) = depths_.at(id);
    for (const auto& [id, p_W] : points_W_) e_.points_W_.at(id) = p_W;  // in place: the priors name them
  }

 private:
  Estimator& e_;
  std::vector<std::array<double, kPoseSize>> poses_;
  std::vector<std::array<double, kSpeedBiasSize>> speed_biases_;
  std::map<int, std::pair<double, bool>> depths_;
  std::map<int, std::array<double, kPointSize>> points_W_;
};

}  // namespace vigil::estimator
