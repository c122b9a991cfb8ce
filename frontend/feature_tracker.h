// KLT feature tracker: grayscale images in, feature tracks (track id + undistorted pixel) out.
//
// The design of VINS-Mono's feature tracker, written anew. Per image, in this order:
//   1. optional CLAHE equalization;
//   2. pyramidal Lucas-Kanade from the previous image into this one; tracks that fail, leave the image
//      (less than border_px from its edge) or, with backward_check, do not track back to where they came from
//      are dropped; with refine_tracks (and subpixel_window_px > 0), each tracked point is refined by
//      cv::cornerSubPix and keeps the refinement when it moved at most subpixel_max_shift_px; with
//      anchor_refinement, each tracked point is then aligned again with the patch of its anchor image (where
//      its track began or was last re-anchored) under an affine warp and keeps that result when it moved at
//      most anchor_max_shift_px; tracks whose anchor is anchor_max_age images old are re-anchored here;
//   3. on a published frame only (at most max_rate_hz, the first image always):
//      a. undistortion of every tracked point (frontend/point_undistorter.h);
//      b. RANSAC fundamental matrix between each track's undistorted pixel at the last published frame and
//         now; outliers are dropped (skipped with fewer than 8 tracks);
//      c. tracks whose undistorted pixel lies outside the image are dropped;
//      d. with max_track_length > 0, tracks of that length end, at most max_features / max_track_length per
//         frame (longest first), so that a track's drift is bounded;
//      e. spacing: tracks are visited longest first (ties: lower id first); a track within min_distance_px
//         (spacing_drop_px when set) of one already kept is dropped;
//      f. new Shi-Tomasi corners (frontend/corner_detector.h: cv::goodFeaturesToTrack's corners, scored only
//         where the mask is open), masked by discs of min_distance_px around the kept tracks, fill up to
//         max_features; with subpixel_window_px > 0 they are refined by cv::cornerSubPix (a refinement that
//         leaves the window or the border is not kept); each gets the next track id.
// Track ids start at 0 and increase by one per new corner, never reused; a track is contiguous over published
// frames (once dropped, its id never returns), which is what the estimator's feature bookkeeping expects.
//
// Output pixels are on the undistorted pinhole image with the raw camera's fx, fy, cx, cy.
//
// Determinism: every step is a deterministic function of the images. OpenCV's RANSAC (cv::findFundamentalMat
// with FM_RANSAC) draws its samples from a generator it seeds itself with a constant on every call, so it
// does not depend on cv::theRNG() or on earlier calls; parallel loops inside OpenCV split work over
// independent pixels or points. The same images in the same order give identical output (tests/frontend).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/camera.h"
#include "core/types.h"
#include "frontend/affine_patch_aligner.h"
#include "frontend/feature_tracker_options.h"
#include "frontend/point_undistorter.h"

namespace vigil::frontend {

// Counters over the images fed so far.
struct TrackerStats {
  int64_t images = 0;
  int64_t published_frames = 0;
  int64_t tracks_created = 0;
  int64_t klt_failures = 0;         // lost by Lucas-Kanade, the image border or the backward check
  int64_t ransac_outliers = 0;      // dropped by the fundamental-matrix RANSAC
  int64_t spacing_drops = 0;        // dropped as too close to a longer track
  int64_t outside_undistorted = 0;  // dropped because the undistorted pixel left the image
  int64_t aged_out = 0;             // ended after max_track_length published frames
  int64_t anchor_refined = 0;       // anchor refinements applied
  int64_t anchor_rejected = 0;      // anchor refinements that failed or moved a point too far
};

class FeatureTracker {
 public:
  FeatureTracker(const FeatureTrackerOptions& options, const CameraModel& camera);

  // Feeds the next image (8-bit, one channel, of the camera's size; timestamps strictly increasing). Returns
  // the frame's observations (ordered by track id) when the frame is published, nothing otherwise. Throws
  // std::invalid_argument on a wrong image type or size or a timestamp that does not increase.
  std::optional<CameraFrame> Track(const cv::Mat& image, int64_t t_ns);

  const TrackerStats& stats() const { return stats_; }
  const CameraModel& camera() const { return camera_; }

 private:
  struct TrackState {
    int id = 0;
    cv::Point2f raw_px;          // in the current image
    cv::Point2f undistorted_px;  // at the last published frame (then: now)
    int length = 0;              // published frames the track was seen in
    // anchor_refinement: the patch around the track's point in its anchor image (none when the point was too
    // close to the border or the patch had too little texture: then the next image tries again), that image's
    // index (stats_.images then) and the warp's linear part, anchor -> current image.
    std::shared_ptr<const AffinePatch> anchor;
    int64_t anchor_image = 0;
    cv::Matx22f anchor_linear = cv::Matx22f::eye();
  };

  bool ShouldPublish(int64_t t_ns) const;
  void TrackIntoImage(const std::vector<cv::Mat>& pyramid);
  void RefineAgainstAnchors(const cv::Mat& image);
  void Anchor(const cv::Mat& image, TrackState* track);
  void RejectWithFundamental(const std::vector<cv::Point2f>& undistorted_now);
  void RefineCorners(const cv::Mat& image, std::vector<cv::Point2f>* points, double max_shift_px) const;
  void EndAgedTracks();
  void EnforceSpacing();
  void DetectNewCorners(const cv::Mat& image);
  bool InsideBorder(const cv::Point2f& p) const;
  bool InsideImage(const cv::Point2f& p) const;

  FeatureTrackerOptions options_;
  CameraModel camera_;
  PointUndistorter undistorter_;
  cv::Ptr<cv::CLAHE> clahe_;
  std::vector<cv::Mat> previous_pyramid_;  // of the previous image (cv::buildOpticalFlowPyramid)
  std::vector<TrackState> tracks_;
  int next_id_ = 0;
  std::optional<int64_t> last_t_ns_, last_published_t_ns_;
  TrackerStats stats_;
};

}  // namespace vigil::frontend
