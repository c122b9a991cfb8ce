// The feature side's reprojection factors, kept across frames: one ReprojectionFactor per (track, anchor
// frame, observing frame), built when a track first has that pair and reused while the track keeps both
// observations.
//
// A factor depends only on the anchor observation and its own (and the fixed camera extrinsics and weight),
// which never change while the pair lives, and frame ids are never reused, so a cached factor is exactly the
// one a fresh build would give. The estimator asks for a track's terms (factor + parameter blocks) whenever
// it builds a problem (the window's optimization, a marginalization); the factors stay owned by the cache.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "estimator/feature_manager.h"
#include "estimator/reprojection_factor.h"

namespace vigil::estimator {

class ReprojectionFactorCache {
 public:
  // A factor and its parameter blocks: anchor pose, observing pose, inverse depth.
  struct Term {
    ReprojectionFactor* factor;
    std::array<double*, 3> blocks;
  };

  // `sqrt_information`: focal length / pixel std (reprojection_factor.h).
  ReprojectionFactorCache(const Eigen::Isometry3d& T_BC, double sqrt_information);

  // Appends one term per observation of track `id` after its anchor, in observation order; `pose_of(frame
  // id)` is a window frame's pose block, `inv_depth` the track's inverse depth (or a solve's copy of it).
  // The track's factors of pairs it no longer has are released.
  void AppendTerms(int id, const FeatureTrack& track, const std::function<double*(uint64_t)>& pose_of,
                   double* inv_depth, std::vector<Term>* terms);
  // Releases the factors of every track not in `tracks`.
  void KeepTracks(const std::map<int, FeatureTrack>& tracks);
  void Clear() { factors_.clear(); }
  // The number of cached factors (of every track).
  std::size_t size() const;

 private:
  struct Entry {
    uint64_t anchor_frame = 0;
    uint64_t frame = 0;
    std::unique_ptr<ReprojectionFactor> factor;
  };

  Eigen::Isometry3d T_BC_;
  double sqrt_information_;
  std::map<int, std::vector<Entry>> factors_;  // per track, oldest observation first
};

}  // namespace vigil::estimator
