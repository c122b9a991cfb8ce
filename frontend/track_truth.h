// The true pixel of every tracked observation, from the true camera poses and the scene's geometry.
//
// A track's first observation defines the scene point it follows: its pixel is back-projected along the
// camera ray at its frame's true pose and intersected with the scene (a ray-cast supplied by the caller, e.g.
// on the rendered scene's mesh). Every later observation of the track should then see that point's projection
// at its own frame's true pose. The first observation is its own truth (error 0 by construction).
//
// Pixels are on the undistorted pinhole image (the tracker's output); projection ignores the image bounds.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/types.h"

namespace vigil::frontend {

struct PinholeIntrinsics {
  double fx = 460.0, fy = 460.0, cx = 320.0, cy = 240.0;
};

// The true camera pose T_WC at a frame time; nothing when unknown (outside the ground truth).
using CameraPoseAt = std::function<std::optional<Eigen::Isometry3d>(int64_t t_ns)>;
// Distance along the unit ray from origin_W in direction dir_W to the first surface hit; nothing on a miss.
using RayCast =
    std::function<std::optional<double>(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W)>;

// truth[f][i] is the true pixel of frames[f].features[i], or nothing when it cannot be known (the first
// observation's ray misses the scene, a pose is unknown, or the point is behind the camera).
using TruePixels = std::vector<std::vector<std::optional<Eigen::Vector2d>>>;

TruePixels ComputeTruePixels(const std::vector<CameraFrame>& frames, const PinholeIntrinsics& intrinsics,
                             const CameraPoseAt& T_WC_at, const RayCast& ray_cast);

}  // namespace vigil::frontend
