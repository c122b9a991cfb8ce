// Vision-only structure from motion over the initialization window, up to scale.
//
// Frames are given as feature maps (track id -> normalized image coordinates). The reference frame L is the
// earliest frame that shares more than `min_correspondences` features with the newest frame, with a mean
// parallax above `min_parallax` and a relative pose accepted by RANSAC. From L and the newest frame the SfM
// triangulates the shared features, localizes the frames after L and then before L by PnP (each from its
// neighbour's pose), triangulating new features as frames get poses, and finishes with a bundle adjustment
// (Ceres) over all poses and points with L's pose and the newest frame's position held fixed (the gauge:
// L is the origin and the L -> newest baseline has unit length).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimator/init/pnp.h"
#include "estimator/init/relative_pose.h"

namespace vigil::estimator {

using FeatureMap = std::map<int, Eigen::Vector2d>;  // track id -> (x/z, y/z)

struct WindowSfmOptions {
  int min_correspondences = 20;        // strictly more are needed
  double min_parallax = 30.0 / 460.0;  // mean parallax (normalized units), strictly more is needed
  RelativePoseOptions relative_pose;
  PnpOptions pnp;
  int min_pnp_points = 10;
  int bundle_adjustment_iterations = 50;
  double max_rms_reprojection = 3.0 / 460.0;  // normalized units
};

struct WindowSfmResult {
  int reference_frame = -1;              // index of L in the window
  std::vector<Eigen::Quaterniond> q_LC;  // camera orientation of each frame in L
  std::vector<Eigen::Vector3d> p_LC;     // camera position of each frame in L (scale: |p_LC[newest]| = 1)
  std::map<int, Eigen::Vector3d> points_L;
  double rms_reprojection = 0.0;  // after bundle adjustment, normalized units
  std::string failure_reason;     // set when WindowSfm returns false
};

// Mean parallax |x_newest - x_i| over the features shared by two frames, and how many are shared.
double MeanParallax(const FeatureMap& a, const FeatureMap& b, int* shared);

bool WindowSfm(const std::vector<FeatureMap>& frames, const WindowSfmOptions& options,
               WindowSfmResult* result);

}  // namespace vigil::estimator
