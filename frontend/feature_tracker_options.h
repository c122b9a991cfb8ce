// Options of the KLT feature tracker (frontend/feature_tracker.h): VINS-Mono's tracker design with its EuRoC
// settings as defaults (Shi-Tomasi corners, quality 0.01, 30 px apart, at most 150; pyramidal Lucas-Kanade
// with a 21 x 21 window over 3 pyramid levels; RANSAC fundamental matrix at 1 px on undistorted points).
#pragma once

#include "core/config.h"

namespace vigil::frontend {

struct FeatureTrackerOptions {
  // Corner detection (Shi-Tomasi, frontend/corner_detector.h: cv::goodFeaturesToTrack's corners).
  int max_features = 150;         // tracks kept per frame; new corners fill up to this count
  double quality_level = 0.01;    // corner score relative to the best corner of the image
  double min_distance_px = 30.0;  // between a new corner and any track, and between kept tracks
  int border_px = 1;              // tracks closer than this to the image border are dropped
  // Sub-pixel corner refinement (cv::cornerSubPix) of new corners and, with refine_tracks, of every tracked
  // point after Lucas-Kanade: the point moves to where the image gradients around it meet (a corner's
  // vertex), so a track stays on its corner instead of drifting with the window's deformation.
  int subpixel_window_px = 0;          // half side of the refinement window (0: no refinement)
  bool refine_tracks = false;          // refine tracked points too (else new corners only)
  double subpixel_max_shift_px = 0.5;  // a refinement moving a tracked point farther is not applied
  int subpixel_iterations = 20;
  double subpixel_epsilon_px = 0.01;
  // Spacing hysteresis: new corners keep min_distance_px from every track, but a tracked point is dropped
  // only when it comes closer than this to a longer track (0: min_distance_px).
  double spacing_drop_px = 0.0;
  // Track refresh: a track published this many times ends (its corner is detected again as a new track), so
  // that no track carries the drift of a long chain of frame-to-frame steps; at most
  // max_features / max_track_length tracks end per frame, the longest first (0: tracks never age out).
  int max_track_length = 0;
  // Pyramidal Lucas-Kanade (cv::calcOpticalFlowPyrLK) from one frame into the next.
  int klt_window_px = 21;          // square search window side
  int klt_pyramid_levels = 3;      // levels above the full image (0: no pyramid)
  int klt_max_iterations = 30;     // per level
  double klt_epsilon_px = 0.01;    // stop when the update is below this
  bool backward_check = false;     // also track back into the previous frame and drop inconsistent tracks
  double backward_check_px = 0.5;  // largest distance between a point and its back-tracked position
  // Anchor refinement (vigil's, not VINS-Mono's): after the frame-to-frame step, each tracked point is
  // aligned again with its anchor, the anchor_patch_px patch around the pixel where its track began (or was
  // last re-anchored), under an affine warp (frontend/affine_patch_aligner.h), starting from the
  // frame-to-frame result and the track's last warp. Frame-to-frame steps each add a small error that
  // accumulates along the track; against the anchor it does not add up, and the affine warp follows the
  // patch's rotation, scale and shear as the view changes (a translation-only Lucas-Kanade from the anchor
  // image does not: it drifts as much as the frame-to-frame chain). A track is re-anchored at the current
  // image every anchor_max_age images. A refinement that fails, or moves the point farther than
  // anchor_max_shift_px from the frame-to-frame result, is not applied.
  bool anchor_refinement = false;
  int anchor_patch_px = 21;   // side of the anchor patch (odd; an even side gets one pixel more)
  int anchor_max_age = 1000;  // images between re-anchorings
  double anchor_max_shift_px = 1.0;
  // Outlier rejection: RANSAC fundamental matrix between the last published frame and this one, on the
  // undistorted pixels.
  bool ransac = true;
  double ransac_threshold_px = 1.0;  // distance to the epipolar line of an inlier
  double ransac_confidence = 0.99;
  // Contrast-limited adaptive histogram equalization of each image before anything else.
  bool clahe = false;
  double clahe_clip_limit = 3.0;
  int clahe_tiles = 8;  // tiles per image side
  // Publication rate: every image is tracked, but at most max_rate_hz frames are published (0: every frame).
  // RANSAC, new corners and the output happen on published frames only.
  double max_rate_hz = 0.0;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("max_features", max_features, "largest number of tracks per frame", Bounds::AtLeast(1));
    v.Field("quality_level", quality_level, "Shi-Tomasi corner quality relative to the best corner",
            Bounds{0.0, 1.0, true, false});
    v.Field("min_distance_px", min_distance_px, "least distance between two tracks [px]",
            Bounds::NonNegative());
    v.Field("border_px", border_px, "tracks closer than this to the image border are dropped [px]",
            Bounds::NonNegative());
    v.Field("subpixel_window_px", subpixel_window_px,
            "half side of the cv::cornerSubPix window refining corners [px] (0: no refinement)",
            Bounds::Closed(0, 15));
    v.Field("refine_tracks", refine_tracks, "also refine every tracked point after Lucas-Kanade");
    v.Field("subpixel_max_shift_px", subpixel_max_shift_px,
            "largest refinement step applied to a tracked point [px]", Bounds::Positive());
    v.Field("subpixel_iterations", subpixel_iterations, "cv::cornerSubPix iterations", Bounds::AtLeast(1));
    v.Field("subpixel_epsilon_px", subpixel_epsilon_px, "cv::cornerSubPix convergence threshold [px]",
            Bounds::Positive());
    v.Field("spacing_drop_px", spacing_drop_px,
            "a track closer than this to a longer one is dropped [px] (0: min_distance_px)",
            Bounds::NonNegative());
    v.Field("max_track_length", max_track_length,
            "a track ends after this many published frames (0: no limit)", Bounds::NonNegative());
    v.Field("klt_window_px", klt_window_px, "Lucas-Kanade window side [px]", Bounds::AtLeast(3));
    v.Field("klt_pyramid_levels", klt_pyramid_levels, "Lucas-Kanade pyramid levels above the full image",
            Bounds::Closed(0, 8));
    v.Field("klt_max_iterations", klt_max_iterations, "Lucas-Kanade iterations per level",
            Bounds::AtLeast(1));
    v.Field("klt_epsilon_px", klt_epsilon_px, "Lucas-Kanade convergence threshold [px]", Bounds::Positive());
    v.Field("backward_check", backward_check,
            "track back into the previous frame and drop inconsistent tracks");
    v.Field("backward_check_px", backward_check_px, "largest forward-backward distance [px]",
            Bounds::Positive());
    v.Field("anchor_refinement", anchor_refinement,
            "vigil's, not VINS-Mono's: align each tracked point again with the patch its track began with, "
            "under an affine warp");
    v.Field("anchor_patch_px", anchor_patch_px, "side of the anchor refinement's patch [px]",
            Bounds::Closed(5, 61));
    v.Field("anchor_max_age", anchor_max_age,
            "images after which a track is re-anchored at the current image", Bounds::AtLeast(1));
    v.Field("anchor_max_shift_px", anchor_max_shift_px,
            "largest anchor refinement step applied to a tracked point [px]", Bounds::Positive());
    v.Field("ransac", ransac, "reject outliers with a RANSAC fundamental matrix on undistorted points");
    v.Field("ransac_threshold_px", ransac_threshold_px, "RANSAC distance to the epipolar line [px]",
            Bounds::Positive());
    v.Field("ransac_confidence", ransac_confidence, "RANSAC confidence", Bounds{0.0, 1.0, true, true});
    v.Field("clahe", clahe, "equalize each image with CLAHE before tracking");
    v.Field("clahe_clip_limit", clahe_clip_limit, "CLAHE contrast limit", Bounds::Positive());
    v.Field("clahe_tiles", clahe_tiles, "CLAHE tiles per image side", Bounds::AtLeast(1));
    v.Field("max_rate_hz", max_rate_hz, "largest published frame rate [Hz] (0: every frame)",
            Bounds::NonNegative());
  }
};

}  // namespace vigil::frontend
