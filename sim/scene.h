// The rendered world of a scenario, chosen by its landmark layout (sim/landmarks.h) so that the images show
// what the landmarks stand for:
//   house: textured planar faces of the house (the 10 m cube with its gable roof whose vertices are
//     sim/landmarks' house points), a ground plane and a few boxes around the ellipse;
//   random: the hall whose walls carry the random landmarks (WallRoom): its four walls, a floor and a
//     ceiling. The floor is the ground z = 0 (or the room's bottom when that is higher) and the walls rise
//     from it to the room's top; the course profile of the rescue trajectory (ramp, platform, bumps) is
//     motion only and is not modelled in the floor;
//   house+random: the house scene and the hall's walls.
//
// Every face is a convex planar polygon (3 or 4 corners) with a texture index, a shade (the texture's gray
// levels are multiplied by it, so that adjacent faces differ) and texture axes: the texture coordinate of a
// point p is ((p - corner0) . u_axis, (p - corner0) . v_axis) / texture_scale_m. Mesh() gives the same
// surfaces as triangles (scene.obj).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/mesh.h"
#include "sim/landmarks.h"
#include "sim/sim_options.h"

namespace vigil::sim {

struct SceneFace {
  std::vector<Eigen::Vector3d> corners_W;  // 3 or 4, counter-clockwise seen from outside
  Eigen::Vector3d u_axis_W, v_axis_W;      // unit texture axes in the face's plane
  int texture = 0;
  float shade = 1.0f;
};

struct Scene {
  std::vector<SceneFace> faces;
  int num_textures = 0;

  TriangleMesh Mesh() const;
};

// The house, the ground (z = 0, 160 m x 160 m around the house) and four 3 m boxes beyond the ellipse.
Scene MakeHouseScene();

// The hall of `room`: walls, floor and ceiling when `closed`, the walls alone otherwise (added to a scene
// that has its own ground).
void AddHall(const WallRoom& room, bool closed, Scene* scene);

// The scene of a scenario with landmarks `options` laid out around `path_W` (sim/landmarks.h).
Scene MakeScene(const LandmarkOptions& options, const std::vector<Eigen::Vector3d>& path_W);

}  // namespace vigil::sim
