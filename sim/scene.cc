#include "sim/scene.h"

namespace vigil::sim {
namespace {

using V3 = Eigen::Vector3d;

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
  const V3 a(lo.x(), lo.y(), lo.z()), b(hi.x(), lo.y(), lo.z()), c(hi.x(), hi.y(), lo.z()), d(lo.x(), hi.y(), lo.z());
  const V3 up(0, 0, hi.z() - lo.z());
  scene->faces.push_back(Face({a, b, b + up, a + up}, texture, 0.95f));
  scene->faces.push_back(Face({b, c, c + up, b + up}, texture, 0.8f));
  scene->faces.push_back(Face({c, d, d + up, c + up}, texture, 0.9f));
  scene->faces.push_back(Face({d, a, a + up, d + up}, texture, 0.75f));
  scene->faces.push_back(Face({a + up, b + up, c + up, d + up}, texture, 1.0f));
}

}  // namespace

Scene MakeScene() {
  Scene s;
  s.num_textures = 4;  // 0: house walls, 1: roof, 2: ground, 3: boxes
  // House (sim/landmarks.cc's vertices 0..9): walls, gables, roof.
  const V3 p0(0, 0, 0), p1(10, 0, 0), p2(10, 10, 0), p3(0, 10, 0);
  const V3 e0(0, 0, 10), e1(10, 0, 10), e2(10, 10, 10), e3(0, 10, 10);
  const V3 r0(5, 0, 14), r1(5, 10, 14);
  s.faces.push_back(Face({p0, p1, e1, e0}, 0, 1.0f));    // y = 0
  s.faces.push_back(Face({p1, p2, e2, e1}, 0, 0.85f));   // x = 10 (the door's face)
  s.faces.push_back(Face({p2, p3, e3, e2}, 0, 0.95f));   // y = 10 (the window's face)
  s.faces.push_back(Face({p3, p0, e0, e3}, 0, 0.8f));    // x = 0
  s.faces.push_back(Face({e0, e1, r0}, 0, 1.0f));        // gable y = 0
  s.faces.push_back(Face({e2, e3, r1}, 0, 0.95f));       // gable y = 10
  s.faces.push_back(Face({e1, e2, r1, r0}, 1, 0.9f));    // roof slope x > 5
  s.faces.push_back(Face({e3, e0, r0, r1}, 1, 0.75f));   // roof slope x < 5
  // Ground.
  s.faces.push_back(Face({V3(-75, -75, 0), V3(85, -75, 0), V3(85, 85, 0), V3(-75, 85, 0)}, 2, 1.0f));
  // Boxes beyond the ellipse (x in [-10, 20], y in [-15, 25]).
  AddBox(V3(27, 3, 0), V3(30, 6, 3), 3, &s);
  AddBox(V3(-20, 4, 0), V3(-17, 7, 3), 3, &s);
  AddBox(V3(4, 32, 0), V3(7, 35, 3), 3, &s);
  AddBox(V3(3, -25, 0), V3(6, -22, 3), 3, &s);
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
