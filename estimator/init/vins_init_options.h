// Options of the VINS-style visual-inertial initialization (`estimator.vins`).
//
// Defaults follow the reference (docs/references.md, "VINS-Mono's estimator"): a reference frame needs more
// than 20 correspondences with the newest frame and more than 30 px mean parallax; the linear alignment fails
// when the estimated |g| is more than 1 m/s^2 away from the nominal gravity or the scale is not positive.
#pragma once

#include <cstdint>

#include "core/config.h"

namespace vigil::estimator {

struct VinsInitOptions {
  int min_correspondences =
      20;  // a reference frame needs MORE than this many features shared with the newest
  double min_parallax_px = 30.0;  // ... and a mean parallax above this (pixels at the camera's fx)
  int ransac_iterations = 200;    // eight-point RANSAC hypotheses for the relative pose
  double ransac_threshold_px =
      2.0;                      // Sampson distance (pixels at fx) below which a correspondence is an inlier
  int min_ransac_inliers = 12;  // fewer inliers: the relative pose is rejected
  uint64_t ransac_seed = 1;     // seed of the RANSAC sample stream (deterministic)
  int min_pnp_points = 10;      // a frame is localized by PnP only with at least this many known landmarks
  int bundle_adjustment_iterations = 50;
  double max_reprojection_px =
      3.0;  // after bundle adjustment, RMS reprojection error above this fails the SfM
  double max_gravity_error_mps2 = 1.0;  // | |g_estimated| - g | above this fails the alignment
  int gravity_refinement_iterations = 4;
  // vigil's gyroscope consistency check, not VINS-Mono's (0 turns it off): after the gyroscope bias is
  // solved, a pair of window frames whose vision and bias-corrected gyroscope rotations still differ by more
  // than this fails the window. A glitch burst inside the window is what the bias cannot explain; without the
  // check the bias absorbs it (the window after a burst gave 0.08 rad/s against a truth of -0.009 rad/s).
  // Clean windows of the paper scenario and the CI sweep stay below 0.51 deg per pair.
  double max_gyro_residual_deg = 3.0;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("min_correspondences", min_correspondences,
            "a reference frame needs more than this many features shared with the newest frame",
            Bounds::AtLeast(7));
    v.Field("min_parallax_px", min_parallax_px,
            "... and a mean parallax to the newest frame above this [px at fx]", Bounds::NonNegative());
    v.Field("ransac_iterations", ransac_iterations, "RANSAC hypotheses of the eight-point relative pose",
            Bounds::AtLeast(1));
    v.Field("ransac_threshold_px", ransac_threshold_px,
            "RANSAC inlier threshold on the Sampson distance [px at fx]", Bounds::Positive());
    v.Field("min_ransac_inliers", min_ransac_inliers, "fewest RANSAC inliers for an accepted relative pose",
            Bounds::AtLeast(8));
    v.Field("ransac_seed", ransac_seed, "seed of the RANSAC sampling stream");
    v.Field("min_pnp_points", min_pnp_points, "fewest triangulated landmarks to localize a frame by PnP",
            Bounds::AtLeast(4));
    v.Field("bundle_adjustment_iterations", bundle_adjustment_iterations,
            "iterations of the window bundle adjustment", Bounds::AtLeast(1));
    v.Field("max_reprojection_px", max_reprojection_px,
            "the SfM fails when its RMS reprojection error after bundle adjustment exceeds this [px at fx]",
            Bounds::Positive());
    v.Field("max_gravity_error_mps2", max_gravity_error_mps2,
            "the alignment fails when the estimated gravity norm differs from g by more than this [m/s^2]",
            Bounds::Positive());
    v.Field("gravity_refinement_iterations", gravity_refinement_iterations,
            "iterations of the gravity refinement on the sphere", Bounds::AtLeast(1));
    v.Field("max_gyro_residual_deg", max_gyro_residual_deg,
            "vigil's check, not VINS-Mono's: the window fails when a pair's vision and bias-corrected "
            "gyroscope rotations differ by more than this after the bias solve, as inside a glitch burst (0: "
            "no check) [deg]",
            Bounds::NonNegative());
  }
};

}  // namespace vigil::estimator
