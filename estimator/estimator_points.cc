// window.oldest_tracks points: the long tracks kept as landmark points in W (OKVIS's design, the fourteenth
// and fifteenth rounds of docs/results/2026-12-estimator-speed.md). When the oldest frame leaves,
// point_settle_s or more after the initialization, each usable track anchored in it with
// point_min_observations observations, whose anchor camera and last camera are apart by
// point_min_baseline_ratio of its depth, becomes a point p_W, while fewer than point_max (if set) are live.
// Its observation in the leaving frame goes into the priors with the point kept; its later observations are
// PointReprojectionFactors on (pose, point), so each observation counts once, and the prior ties the window
// to the track's past for as long as it is seen. A point leaves the priors (marginalized) when its track
// ends: with the next keyframe's oldest frame, when both priors hold it. The other tracks re-anchor
// (VINS-Mono).
#include <algorithm>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

#include "estimator/estimator.h"
#include "estimator/point_reprojection_factor.h"

namespace vigil::estimator {

std::vector<double*> Estimator::PointBlocks() {
  std::vector<double*> blocks;
  for (auto& [id, p_W] : points_W_) blocks.push_back(p_W.data());
  return blocks;
}

void Estimator::AppendPointTerms(std::vector<std::unique_ptr<ceres::CostFunction>>* costs,
                                 std::vector<MarginalizationTerm>* terms, std::optional<uint64_t> frame_id) {
  const double sqrt_information = camera_.fx / options_.features.pixel_std_px;
  for (auto& [id, p_W] : points_W_) {
    if (PointIsLost(id)) continue;
    const FeatureTrack& track = features_.tracks().at(id);
    for (const auto& [frame, n] : track.observations) {
      if (frame_id && frame != *frame_id) continue;
      auto factor = std::make_unique<PointReprojectionFactor>(n, T_BC_, sqrt_information);
      terms->push_back({factor.get(), &loss_, {FrameById(frame).pose, p_W.data()}});
      costs->push_back(std::move(factor));
    }
  }
}

void Estimator::MakePointsOfOldest() {
  const Frame& oldest = *window_.front();
  if (!points_from_ns_ || oldest.t_ns < *points_from_ns_) return;
  const Eigen::Isometry3d T_WC_anchor = T_WC(oldest);
  const WindowOptions& o = options_.window;
  for (auto& [id, track] : features_.tracks()) {
    if (o.point_max > 0 && static_cast<int>(points_W_.size()) >= o.point_max) return;
    if (!IsDepthTrack(id, track) || track.anchor_frame() != oldest.id ||
        static_cast<int>(track.observations.size()) < o.point_min_observations)
      continue;
    const Eigen::Vector3d c_last_W = T_WC(FrameById(track.observations.back().first)).translation();
    const double baseline_m = (c_last_W - T_WC_anchor.translation()).norm();
    if (baseline_m * track.inv_depth < o.point_min_baseline_ratio) continue;
    const Eigen::Vector2d& n = track.observations.front().second;
    const Eigen::Vector3d p_W = T_WC_anchor * (Eigen::Vector3d(n.x(), n.y(), 1.0) / track.inv_depth);
    points_W_[id] = {p_W.x(), p_W.y(), p_W.z()};
  }
}

void Estimator::SyncPointDepths() {
  for (const auto& [id, p_W] : points_W_) {
    const auto it = features_.tracks().find(id);
    if (it == features_.tracks().end()) continue;
    const Eigen::Vector3d p_C =
        T_WC(FrameById(it->second.anchor_frame())).inverse() * Eigen::Vector3d(p_W[0], p_W[1], p_W[2]);
    if (p_C.z() > 0.0) it->second.inv_depth = 1.0 / p_C.z();
  }
}

bool Estimator::PointIsLost(int id) const { return features_.tracks().count(id) == 0; }

std::vector<const double*> Estimator::LostPoints() const {
  std::vector<const double*> lost;
  for (const auto& [id, p_W] : points_W_)
    if (PointIsLost(id)) lost.push_back(p_W.data());
  return lost;
}

void Estimator::ErasePoints(const std::vector<const double*>& points) {
  for (auto it = points_W_.begin(); it != points_W_.end();)
    it = std::find(points.begin(), points.end(), it->second.data()) != points.end() ? points_W_.erase(it)
                                                                                    : std::next(it);
}

void Estimator::DropLostPoints() {
  // A lost point both priors hold waits for the next keyframe, whose marginalization eliminates it with the
  // oldest frame (one factorization of each prior); the others leave both priors now, all in one elimination.
  const auto holds = [](const std::shared_ptr<LinearPrior>& prior, const double* point) {
    return prior && prior->Involves(point);
  };
  std::vector<const double*> now;
  for (const double* point : LostPoints())
    if (!holds(prior_, point) || (options_.pose_covariance && !holds(anchored_prior_, point)))
      now.push_back(point);
  if (now.empty()) return;
  const auto involves = [&](const std::shared_ptr<LinearPrior>& prior) {
    return std::any_of(now.begin(), now.end(), [&](const double* point) { return holds(prior, point); });
  };
  const PriorUpdate update = [&](const LinearPrior* previous, PriorForm form, LinearPrior* prior) {
    SchurComplement schur;
    const double threshold = options_.window.marginalization_eigen_threshold;
    return EliminateDropped(previous, {}, now, threshold, &schur) &&
           PriorOfSchurComplement(std::move(schur), threshold, form, prior);
  };
  if (involves(prior_)) KeepPrior(update);
  if (involves(anchored_prior_)) KeepAnchoredPrior(update);
  ErasePoints(now);
}

}  // namespace vigil::estimator
