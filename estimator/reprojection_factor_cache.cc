#include "estimator/reprojection_factor_cache.h"

namespace vigil::estimator {

ReprojectionFactorCache::ReprojectionFactorCache(const Eigen::Isometry3d& T_BC, double sqrt_information)
    : T_BC_(T_BC), sqrt_information_(sqrt_information) {}

void ReprojectionFactorCache::AppendTerms(int id, const FeatureTrack& track,
                                          const std::function<double*(uint64_t)>& pose_of, double* inv_depth,
                                          std::vector<Term>* terms) {
  const auto& [anchor_id, n_anchor] = track.observations.front();
  double* anchor_pose = pose_of(anchor_id);
  std::vector<Entry>& cached = factors_[id];
  // The common case, a track unchanged since its last terms: every cached factor as it is.
  const std::size_t pairs = track.observations.size() - 1;
  bool unchanged = cached.size() == pairs;
  for (std::size_t k = 0; unchanged && k < pairs; ++k)
    unchanged = cached[k].anchor_frame == anchor_id && cached[k].frame == track.observations[k + 1].first;
  if (unchanged) {
    for (const Entry& e : cached)
      terms->push_back({e.factor.get(), {anchor_pose, pose_of(e.frame), inv_depth}});
    return;
  }
  // Reuse the cached factor of every (anchor, frame) pair still observed (both lists are oldest first).
  std::vector<Entry> current;
  current.reserve(track.observations.size() - 1);
  std::size_t c = 0;
  for (std::size_t k = 1; k < track.observations.size(); ++k) {
    const auto& [frame_id, n] = track.observations[k];
    while (c < cached.size() && cached[c].anchor_frame == anchor_id && cached[c].frame < frame_id) ++c;
    if (c < cached.size() && cached[c].anchor_frame == anchor_id && cached[c].frame == frame_id)
      current.push_back(std::move(cached[c]));
    else
      current.push_back(
          {anchor_id, frame_id, std::make_unique<ReprojectionFactor>(n_anchor, n, T_BC_, sqrt_information_)});
    terms->push_back({current.back().factor.get(), {anchor_pose, pose_of(frame_id), inv_depth}});
  }
  cached = std::move(current);
}

void ReprojectionFactorCache::KeepTracks(const std::map<int, FeatureTrack>& tracks) {
  for (auto it = factors_.begin(); it != factors_.end();)
    it = tracks.count(it->first) ? std::next(it) : factors_.erase(it);
}

std::size_t ReprojectionFactorCache::size() const {
  std::size_t n = 0;
  for (const auto& [id, entries] : factors_) n += entries.size();
  return n;
}

}  // namespace vigil::estimator
