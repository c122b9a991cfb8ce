#include "estimator/feature_manager.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "estimator/init/triangulation.h"

namespace vigil::estimator {

int FeatureManager::AddFrame(uint64_t frame_id, const std::map<int, Eigen::Vector2d>& features_n) {
  int tracked = 0;
  for (const auto& [id, n] : features_n) {
    FeatureTrack& track = tracks_[id];
    if (!track.observations.empty()) ++tracked;
    track.observations.emplace_back(frame_id, n);
  }
  return tracked;
}

double FeatureManager::MeanParallax(uint64_t frame_a, uint64_t frame_b, const Eigen::Matrix3d& R_CbCa) const {
  double sum = 0.0;
  int count = 0;
  for (const auto& [id, track] : tracks_) {
    const Eigen::Vector2d* a = nullptr;
    const Eigen::Vector2d* b = nullptr;
    for (const auto& [frame, n] : track.observations) {
      if (frame == frame_a) a = &n;
      if (frame == frame_b) b = &n;
    }
    if (a == nullptr || b == nullptr) continue;
    const Eigen::Vector3d ray_in_b = R_CbCa * Eigen::Vector3d(a->x(), a->y(), 1.0);
    if (ray_in_b.z() <= 0.0) continue;
    sum += (ray_in_b.head<2>() / ray_in_b.z() - *b).norm();
    ++count;
  }
  return count == 0 ? 0.0 : sum / count;
}

namespace {

Eigen::Vector3d Ray(const Eigen::Vector2d& n) { return Eigen::Vector3d(n.x(), n.y(), 1.0); }

}  // namespace

void FeatureManager::SetPoint(int id, const Eigen::Vector3d& p_W, const CameraPoseLookup& T_WC) {
  auto it = tracks_.find(id);
  if (it == tracks_.end()) return;
  const double depth = (T_WC(it->second.anchor_frame()).inverse() * p_W).z();
  it->second.has_depth = DepthInRange(depth);
  if (it->second.has_depth) it->second.inv_depth = 1.0 / depth;
}

void FeatureManager::RemoveFrame(uint64_t frame_id, const CameraPoseLookup& T_WC) {
  for (auto it = tracks_.begin(); it != tracks_.end();) {
    FeatureTrack& track = it->second;
    auto& obs = track.observations;
    const auto pos = std::find_if(obs.begin(), obs.end(), [&](const auto& o) { return o.first == frame_id; });
    if (pos == obs.end()) {
      ++it;
      continue;
    }
    const bool was_anchor = pos == obs.begin();
    const Eigen::Vector3d ray = Ray(obs.front().second);
    obs.erase(pos);
    if (obs.empty()) {
      it = tracks_.erase(it);
      continue;
    }
    if (was_anchor && track.has_depth) {
      const Eigen::Vector3d p_W = T_WC(frame_id) * (ray / track.inv_depth);
      const double depth = (T_WC(obs.front().first).inverse() * p_W).z();
      track.has_depth = DepthInRange(depth);
      if (track.has_depth) track.inv_depth = 1.0 / depth;
    }
    ++it;
  }
}

void FeatureManager::Triangulate(const CameraPoseLookup& T_WC) {
  for (auto& [id, track] : tracks_) {
    if (track.has_depth || track.observations.size() < 2) continue;
    // DLT in the anchor camera frame: each observing camera's projection of anchor-frame points.
    const Eigen::Isometry3d T_WA = T_WC(track.anchor_frame());
    std::vector<Projection> views;
    std::vector<Eigen::Vector2d> observations;
    for (const auto& [frame, n] : track.observations) {
      const Eigen::Isometry3d T_CA = T_WC(frame).inverse() * T_WA;
      Projection P;
      P << T_CA.rotation(), T_CA.translation();
      views.push_back(P);
      observations.push_back(n);
    }
    Eigen::Vector3d p_A;
    if (!TriangulateDlt(views, observations, &p_A)) continue;
    const double depth = p_A.z();
    if (std::isfinite(depth) && DepthInRange(depth)) {
      track.inv_depth = 1.0 / depth;
      track.has_depth = true;
    }
  }
}

int FeatureManager::RemoveOutliers(const CameraPoseLookup& T_WC, double focal_px) {
  int erased = 0;
  for (auto it = tracks_.begin(); it != tracks_.end();) {
    FeatureTrack& track = it->second;
    if (!track.has_depth) {
      ++it;
      continue;
    }
    if (!std::isfinite(track.inv_depth) || track.inv_depth <= 0.0 || !DepthInRange(1.0 / track.inv_depth)) {
      track.has_depth = false;
      ++it;
      continue;
    }
    const Eigen::Vector3d p_W =
        T_WC(track.anchor_frame()) * (Ray(track.observations.front().second) / track.inv_depth);
    double sum_px = 0.0;
    for (const auto& [frame, n] : track.observations) {
      const Eigen::Vector3d p_C = T_WC(frame).inverse() * p_W;
      sum_px += p_C.z() > 0.0 ? focal_px * (p_C.head<2>() / p_C.z() - n).norm() : 1e9;
    }
    if (sum_px / static_cast<double>(track.observations.size()) > options_.outlier_threshold_px) {
      it = tracks_.erase(it);
      ++erased;
    } else {
      ++it;
    }
  }
  return erased;
}

}  // namespace vigil::estimator
