// Feature tracks inside the sliding window.
//
// A track holds the normalized observations (x/z, y/z in C) of one feature id in the window frames that saw
// it, oldest first; the first observation anchors it, and its depth is the inverse depth `inv_depth` along
// the anchor's ray (a window solve works on a copy of it; marginalization uses its address, stable since
// tracks live in a std::map). Frames are named by a unique id (never reused), so sliding the window renumbers
// nothing.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimator/estimator_options.h"

namespace vigil::estimator {

struct FeatureTrack {
  std::vector<std::pair<uint64_t, Eigen::Vector2d>>
      observations;        // (frame id, normalized point), oldest first
  double inv_depth = 0.0;  // [1/m] in the anchor (first observing) frame
  bool has_depth = false;

  uint64_t anchor_frame() const { return observations.front().first; }
};

// Camera pose T_WC of a window frame by its id.
using CameraPoseLookup = std::function<Eigen::Isometry3d(uint64_t frame_id)>;

class FeatureManager {
 public:
  explicit FeatureManager(const FeatureOptions& options) : options_(options) {}

  // Adds the observations of a new frame; returns how many of them continue an existing track.
  int AddFrame(uint64_t frame_id, const std::map<int, Eigen::Vector2d>& features_n);
  // Mean distance on the normalized plane between two frames over the features both saw (0 when none). Each
  // observation in frame_a is first rotated into frame_b by R_CbCa (identity: the raw image displacement;
  // the frames' relative rotation: the parallax of translation alone, VINS-Mono's rotation compensation);
  // a ray that R_CbCa turns behind frame_b's camera is skipped.
  double MeanParallax(uint64_t frame_a, uint64_t frame_b,
                      const Eigen::Matrix3d& R_CbCa = Eigen::Matrix3d::Identity()) const;
  // Removes a frame's observations. A track anchored there moves its depth to its next observation's frame
  // (computed with `T_WC`, valid for both frames); tracks left without observations are erased.
  void RemoveFrame(uint64_t frame_id, const CameraPoseLookup& T_WC);
  // Erases a track with all its observations; a later observation of the same id starts a new track.
  void EraseTrack(int id) { tracks_.erase(id); }
  // Linear triangulation of every track without a depth and with enough observations; keeps depths within the
  // configured range.
  void Triangulate(const CameraPoseLookup& T_WC);
  // Drops depths outside the configured range (they are re-triangulated) and erases tracks whose mean
  // reprojection error exceeds the threshold; returns how many tracks were erased.
  int RemoveOutliers(const CameraPoseLookup& T_WC, double focal_px);
  // Whether a track enters the optimization.
  bool Usable(const FeatureTrack& track) const {
    return track.has_depth && static_cast<int>(track.observations.size()) >= options_.min_observations;
  }
  // Sets the depth of a track from a point in W (e.g. from the initializer).
  void SetPoint(int id, const Eigen::Vector3d& p_W, const CameraPoseLookup& T_WC);
  void Clear() { tracks_.clear(); }

  std::map<int, FeatureTrack>& tracks() { return tracks_; }
  const std::map<int, FeatureTrack>& tracks() const { return tracks_; }

 private:
  bool DepthInRange(double depth_m) const {
    return depth_m >= options_.min_depth_m && depth_m <= options_.max_depth_m;
  }

  FeatureOptions options_;
  std::map<int, FeatureTrack> tracks_;
};

}  // namespace vigil::estimator
