// 3-D point landmarks of the simulated world.
//
// house (ids 0..35): the reference simulator's wire-frame house, 18 distinct vertices plus each vertex
// shifted by (0.5, 0.5, -0.5). vigil's house is a 10 m cube standing on z = 0 with x, y in [0, 10] (centred
// on the ellipse's centre (5, 5)), a gable roof whose ridge runs along y at z = 14, a door on the x = 10 face
// and a window on the y = 10 face (coordinates in landmarks.cc). random: `random_count` points on the four
// vertical walls of a rectangular room that encloses the path's horizontal bounding box with a margin of
// `random_margin_m`; each point is uniform over the walls' total length and over heights [min z of the path -
// h/2, max z of the path + h/2], h = `random_height_m` (stream "landmarks"). Ids follow the house's when both
// are used.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/types.h"
#include "sim/sim_options.h"

namespace vigil::sim {

// The room of the random layout: four vertical walls x = x0, x = x1, y = y0, y = y1 (x0 < x1, y0 < y1)
// spanning heights [z0, z1] [m, W].
struct WallRoom {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0, z0 = 0, z1 = 0;
};

// The room around `path_W` (non-empty): its horizontal bounding box widened by `margin_m` on every side, and
// its height range widened by height_m / 2 below and above.
WallRoom RoomAround(const std::vector<Eigen::Vector3d>& path_W, double margin_m, double height_m);

// The 36 house points, ids 0..35.
std::vector<Landmark> HouseLandmarks();

// `count` points on the walls around `path_W` (positions along the trajectory), ids first_id, first_id + 1,
// ...
std::vector<Landmark> RandomWallLandmarks(int count, const std::vector<Eigen::Vector3d>& path_W,
                                          double margin_m, double height_m, uint64_t seed, int first_id);

// The landmarks selected by `options`.
std::vector<Landmark> MakeLandmarks(const LandmarkOptions& options,
                                    const std::vector<Eigen::Vector3d>& path_W, uint64_t seed);

}  // namespace vigil::sim
