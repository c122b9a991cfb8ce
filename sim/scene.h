// The rendered world: textured planar faces of the house (the 10 m cube with its gable roof whose vertices
// are sim/landmarks' house points), a ground plane and a few boxes around the ellipse.
//
// Every face is a convex planar polygon (3 or 4 corners) with a texture index, a shade (the texture's gray
// levels are multiplied by it, so that adjacent faces differ) and texture axes: the texture coordinate of a
// point p is ((p - corner0) . u_axis, (p - corner0) . v_axis) / texture_scale_m. Mesh() gives the same
// surfaces as triangles (scene.obj).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/mesh.h"

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
Scene MakeScene();

}  // namespace vigil::sim
