#include "sim/scene.h"

#include <algorithm>

namespace vigil::sim {
namespace {

using V3 = Eigen::Vector3d;

// Texture indices, shared by the house and the hall.
constexpr int kWallTexture = 0, kRoofTexture = 1, kGroundTexture = 2, kBoxTexture = 3, kNumTextures = 4;

// A face with u along the first edge and v completing the in-plane basis.
SceneFace Face(std::vector<V3> corners, int texture, float shade) {
  SceneFace f;
  f.corners_W = std::move(corners);
  const V3 e1 = (f.corners_W[1] - f.corners_W[0]).normalized();
  const V3 n = e1.cross(f.corners_W.back() - f.corners_W[0]).normalized();
  f.u_axis_W = e1;
  f.v_axis_W = n.cross(e1);
  f.texture = texture;
  f.shade = shade;
  return f;
}

// The 5 visible faces of an axis-aligned box standing on the ground.
void AddBox(const V3& lo, const V3& hi, int texture, Scene* scene) {
  const V3 a(lo.x(), lo.y(), lo.z()), b(hi.x(), lo.y(), lo.z()), c(hi.x(), hi.y(), lo.z()),
      d(lo.x(), hi.y(), lo.z());
  const V3 up(0, 0, hi.z() - lo.z());
  scene->faces.push_back(Face({a, b, b + up, a + up}, texture, 0.95f));
  scene->faces.push_back(Face({b, c, c + up, b + up}, texture, 0.8f));
  scene->faces.push_back(Face({c, d, d + up, c + up}, texture, 0.9f));
  scene->faces.push_back(Face({d, a, a + up, d + up}, texture, 0.75f));
  scene->faces.push_back(Face({a + up, b + up, c + up, d + up}, texture, 1.0f));
}

}  // namespace

Scene MakeHouseScene() {
  Scene s;
  s.num_textures = kNumTextures;
  // House (sim/landmarks.cc's vertices 0..9): walls, gables, roof.
  const V3 p0(0, 0, 0), p1(10, 0, 0), p2(10, 10, 0), p3(0, 10, 0);
  const V3 e0(0, 0, 10), e1(10, 0, 10), e2(10, 10, 10), e3(0, 10, 10);
  const V3 r0(5, 0, 14), r1(5, 10, 14);
  s.faces.push_back(Face({p0, p1, e1, e0}, kWallTexture, 1.0f));   // y = 0
  s.faces.push_back(Face({p1, p2, e2, e1}, kWallTexture, 0.85f));  // x = 10 (the door's face)
  s.faces.push_back(Face({p2, p3, e3, e2}, kWallTexture, 0.95f));  // y = 10 (the window's face)
  s.faces.push_back(Face({p3, p0, e0, e3}, kWallTexture, 0.8f));   // x = 0
  s.faces.push_back(Face({e0, e1, r0}, kWallTexture, 1.0f));       // gable y = 0
  s.faces.push_back(Face({e2, e3, r1}, kWallTexture, 0.95f));      // gable y = 10
  s.faces.push_back(Face({e1, e2, r1, r0}, kRoofTexture, 0.9f));   // roof slope x > 5
  s.faces.push_back(Face({e3, e0, r0, r1}, kRoofTexture, 0.75f));  // roof slope x < 5
  // Ground.
  s.faces.push_back(
      Face({V3(-75, -75, 0), V3(85, -75, 0), V3(85, 85, 0), V3(-75, 85, 0)}, kGroundTexture, 1.0f));
  // Boxes beyond the ellipse (x in [-10, 20], y in [-15, 25]).
  AddBox(V3(27, 3, 0), V3(30, 6, 3), kBoxTexture, &s);
  AddBox(V3(-20, 4, 0), V3(-17, 7, 3), kBoxTexture, &s);
  AddBox(V3(4, 32, 0), V3(7, 35, 3), kBoxTexture, &s);
  AddBox(V3(3, -25, 0), V3(6, -22, 3), kBoxTexture, &s);
  return s;
}

void AddHall(const WallRoom& room, bool closed, Scene* scene) {
  const double z0 = std::max(room.z0, 0.0), z1 = room.z1;
  // Corners counter-clockwise seen from inside the hall (the side the camera is on).
  const V3 a(room.x0, room.y0, z0), b(room.x1, room.y0, z0), c(room.x1, room.y1, z0), d(room.x0, room.y1, z0);
  const V3 up(0, 0, z1 - z0);
  scene->faces.push_back(Face({b, a, a + up, b + up}, kWallTexture, 1.0f));   // y = y0
  scene->faces.push_back(Face({c, b, b + up, c + up}, kWallTexture, 0.85f));  // x = x1
  scene->faces.push_back(Face({d, c, c + up, d + up}, kWallTexture, 0.95f));  // y = y1
  scene->faces.push_back(Face({a, d, d + up, a + up}, kWallTexture, 0.8f));   // x = x0
  if (!closed) return;
  scene->faces.push_back(Face({a, b, c, d}, kGroundTexture, 1.0f));                    // floor
  scene->faces.push_back(Face({d + up, c + up, b + up, a + up}, kRoofTexture, 0.9f));  // ceiling
}

Scene MakeScene(const LandmarkOptions& options, const std::vector<Eigen::Vector3d>& path_W) {
  const bool house = options.layout != LandmarkLayout::kRandom;
  Scene s = house ? MakeHouseScene() : Scene{{}, kNumTextures};
  if (options.layout != LandmarkLayout::kHouse && !path_W.empty())
    AddHall(RoomAround(path_W, options.random_margin_m, options.random_height_m), !house, &s);
  return s;
}

TriangleMesh Scene::Mesh() const {
  TriangleMesh m;
  for (const SceneFace& f : faces) {
    const int first = static_cast<int>(m.vertices_W.size());
    for (const V3& c : f.corners_W) m.vertices_W.push_back(c);
    for (std::size_t j = 1; j + 1 < f.corners_W.size(); ++j)
      m.triangles.push_back({first, first + static_cast<int>(j), first + static_cast<int>(j) + 1});
  }
  return m;
}

}  // namespace vigil::sim
