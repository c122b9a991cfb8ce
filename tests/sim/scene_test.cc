#include "sim/scene.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "core/config.h"
#include "experiments/runs/run_config.h"
#include "sim/landmarks.h"
#include "sim/simulator.h"

namespace vigil::sim {
namespace {

// Whether `p` lies on a face of `mesh`: a ray from `from` towards it hits the mesh at p itself.
bool OnMesh(const TriangleMesh& mesh, const Eigen::Vector3d& from, const Eigen::Vector3d& p) {
  const std::optional<double> s = RayCast(mesh, from, p - from);
  return s && std::abs(*s - 1.0) < 1e-6;
}

TEST(Scene, RandomLayoutIsTheHallThatCarriesItsLandmarks) {
  const std::vector<Eigen::Vector3d> path = {{0, 0, 0.5}, {10, 4, 0.7}, {3, 8, 0.3}};
  LandmarkOptions options;
  options.layout = LandmarkLayout::kRandom;
  options.random_margin_m = 2.0;
  options.random_height_m = 4.0;
  const TriangleMesh mesh = MakeScene(options, path).Mesh();
  EXPECT_EQ(mesh.triangles.size(), 12u);  // 4 walls, floor, ceiling
  const WallRoom room = RoomAround(path, options.random_margin_m, options.random_height_m);
  int checked = 0;
  for (const Landmark& l : RandomWallLandmarks(200, path, 2.0, 4.0, 3, 0)) {
    if (l.p_W.z() < 0.0) continue;  // below the floor (z = 0): on the walls' extension the hall does not show
    EXPECT_TRUE(OnMesh(mesh, path[0], l.p_W)) << l.p_W.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 100);
  // Closed: every direction from inside hits the hall, the floor at z = 0 and the ceiling at the room's top.
  EXPECT_NEAR(*RayCast(mesh, path[0], {0, 0, -1}), 0.5, 1e-9);
  EXPECT_NEAR(*RayCast(mesh, path[0], {0, 0, 1}), room.z1 - 0.5, 1e-9);
  for (double a = 0.0; a < 6.28; a += 0.1)
    EXPECT_TRUE(RayCast(mesh, path[0], {std::cos(a), std::sin(a), 0.3}).has_value()) << a;
}

TEST(Scene, HouseLayoutIsTheHouseSceneAndHouseAndRandomAddsTheWalls) {
  const std::vector<Eigen::Vector3d> path = {{-10, -15, 5}, {20, 25, 5}};
  LandmarkOptions options;
  const std::size_t house = MakeHouseScene().faces.size();
  EXPECT_EQ(MakeScene(options, path).faces.size(), house);
  options.layout = LandmarkLayout::kHouseAndRandom;
  EXPECT_EQ(MakeScene(options, path).faces.size(), house + 4);  // the house's ground, no ceiling
}

// The rescue course (configs/rescue.yaml) is rendered in its hall: the backward camera's optical axis meets a
// wall of the hall (the floor only while it looks down from the ramp), never the house of the paper scenario
// that stands across the course.
TEST(Scene, RescueCourseCameraSeesTheHallWallsAlongTheWholeLoop) {
  const experiments::RunConfig config =
      experiments::LoadRunConfig(std::string(VIGIL_SOURCE_DIR) + "/configs/rescue.yaml");
  const TriangleMesh mesh = ScenarioScene(config.sim, *MakeTrajectoryModel(config.sim.trajectory)).Mesh();
  const Dataset d = Simulate(config.sim, config.seed);
  const WallRoom room = RoomAround({{-6, -4, 0}, {6, 4, 0}}, config.sim.landmarks.random_margin_m, 0.0);
  int frames = 0, on_walls = 0;
  for (std::size_t k = 0; k < d.groundtruth.size(); k += 100) {
    const NavState& s = d.groundtruth[k];
    Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
    T_WB.linear() = s.q_WB.toRotationMatrix();
    T_WB.translation() = s.p_W;
    const Eigen::Isometry3d T_WC = T_WB * d.camera.T_BC_iso();
    const std::optional<Eigen::Vector3d> hit = PixelRayHit(mesh, d.camera, T_WC, {d.camera.cx, d.camera.cy});
    ASSERT_TRUE(hit.has_value()) << "t " << s.t_ns;
    const bool on_wall = std::abs(hit->x() - room.x0) < 0.5 || std::abs(hit->x() - room.x1) < 0.5 ||
                         std::abs(hit->y() - room.y0) < 0.5 || std::abs(hit->y() - room.y1) < 0.5;
    const bool on_floor = std::abs(hit->z()) < 1e-6;
    EXPECT_TRUE(on_wall || on_floor) << hit->transpose();
    ++frames;
    on_walls += on_wall ? 1 : 0;
  }
  EXPECT_GE(on_walls, frames * 9 / 10);
}

}  // namespace
}  // namespace vigil::sim
