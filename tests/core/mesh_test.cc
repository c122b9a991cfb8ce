#include "core/mesh.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil {
namespace {

// A unit square on the plane z = 2 (two triangles) and a bigger one behind it at z = 5.
TriangleMesh TwoSquares() {
  TriangleMesh m;
  m.vertices_W = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2},
                  {-9, -9, 5}, {9, -9, 5}, {9, 9, 5}, {-9, 9, 5}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  return m;
}

TEST(Mesh, RayCastFindsTheFirstHit) {
  const TriangleMesh m = TwoSquares();
  EXPECT_NEAR(*RayCast(m, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.2, 0.3, 1)), 2.0, 1e-12);
  EXPECT_NEAR(*RayCast(m, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.6, 0, 1)), 5.0,
              1e-12);                                                            // misses the front
  EXPECT_FALSE(RayCast(m, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, -1)));  // behind
  EXPECT_FALSE(RayCast(m, Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 0, 1)));   // beside
  EXPECT_NEAR(*RayCast(m, Eigen::Vector3d(0, 0, 3), Eigen::Vector3d(0, 0, 1)), 2.0, 1e-12);  // from between
}

TEST(Mesh, PixelRayHitProjectsBackToThePixel) {
  const TriangleMesh m = TwoSquares();
  CameraModel cam;
  Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();
  T_WC.translation() = Eigen::Vector3d(0.1, -0.2, -1.0);
  T_WC.linear() = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY()).toRotationMatrix();
  for (const Eigen::Vector2d& uv : {Eigen::Vector2d(300, 260), Eigen::Vector2d(20, 600)}) {
    const std::optional<Eigen::Vector3d> p_W = PixelRayHit(m, cam, T_WC, uv);
    ASSERT_TRUE(p_W);
    EXPECT_TRUE(std::abs(p_W->z() - 2.0) < 1e-9 || std::abs(p_W->z() - 5.0) < 1e-9);
    Eigen::Vector2d back;
    ASSERT_TRUE(cam.Project(T_WC.inverse() * *p_W, &back));
    EXPECT_LT((back - uv).norm(), 1e-9);
  }
}

TEST(Mesh, ObjRoundTripAndErrors) {
  const TriangleMesh m = TwoSquares();
  const TriangleMesh back = ReadMeshObj(TextFile{"scene.obj", MeshObj(m)});
  EXPECT_EQ(back.vertices_W, m.vertices_W);
  EXPECT_EQ(back.triangles, m.triangles);
  // Quads are fanned, i/t/n indices accepted, other lines ignored.
  const TriangleMesh quad = ReadMeshObj(
      TextFile{"q.obj", "mtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1 4/1\n"});
  EXPECT_EQ(quad.triangles.size(), 2u);
  EXPECT_EQ(vigil::testing::InputErrorOf([] {
              ReadMeshObj(TextFile{"s.obj", "v 0 0 0\nv 1 0\n"});
            }),
            "s.obj:2: v: expected 3 finite coordinates");
  EXPECT_EQ(vigil::testing::InputErrorOf([] {
              ReadMeshObj(TextFile{"s.obj", "v 0 0 0\n\nf 1 2 3\n"});
            }),
            "s.obj:3: f: vertex index 2 is out of range (1 vertices)");
}

}  // namespace
}  // namespace vigil
