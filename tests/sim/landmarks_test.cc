#include "sim/landmarks.h"

#include <set>

#include <gtest/gtest.h>

namespace vigil::sim {
namespace {

TEST(Landmarks, HouseHas18DistinctVerticesAndTheirShiftedCopies) {
  const auto house = HouseLandmarks();
  ASSERT_EQ(house.size(), 36u);
  std::set<std::tuple<double, double, double>> distinct;
  for (std::size_t i = 0; i < 36; ++i) {
    EXPECT_EQ(house[i].id, static_cast<int>(i));
    distinct.insert({house[i].p_W.x(), house[i].p_W.y(), house[i].p_W.z()});
  }
  EXPECT_EQ(distinct.size(), 36u);
  for (std::size_t i = 0; i < 18; ++i)
    EXPECT_EQ(house[i + 18].p_W - house[i].p_W, Eigen::Vector3d(0.5, 0.5, -0.5));
  // A 10 m cube (plus roof) inside the ellipse ((x - 5) / 15)^2 + ((y - 5) / 20)^2 = 1.
  for (const auto& l : house) {
    const double x = (l.p_W.x() - 5) / 15, y = (l.p_W.y() - 5) / 20;
    EXPECT_LT(x * x + y * y, 0.5);
  }
}

TEST(Landmarks, RandomPointsLieOnTheWallsAroundThePath) {
  const std::vector<Eigen::Vector3d> path = {{0, 0, 1}, {10, 4, 2}, {3, 8, 1.5}};
  const auto pts = RandomWallLandmarks(500, path, 2.0, 4.0, 9, 36);
  ASSERT_EQ(pts.size(), 500u);
  int per_wall[4] = {0, 0, 0, 0};
  for (const auto& l : pts) {
    const Eigen::Vector3d& p = l.p_W;
    const bool on_wall = p.x() == -2.0 || p.x() == 12.0 || p.y() == -2.0 || p.y() == 10.0;
    EXPECT_TRUE(on_wall) << p.transpose();
    EXPECT_GE(p.x(), -2.0);
    EXPECT_LE(p.x(), 12.0);
    EXPECT_GE(p.y(), -2.0);
    EXPECT_LE(p.y(), 10.0);
    EXPECT_GE(p.z(), -1.0);
    EXPECT_LE(p.z(), 4.0);
    per_wall[p.y() == -2.0 ? 0 : p.x() == 12.0 ? 1 : p.y() == 10.0 ? 2 : 3] += 1;
  }
  EXPECT_EQ(pts.front().id, 36);
  EXPECT_EQ(pts.back().id, 535);
  // Uniform over the perimeter 2 (14 + 12) = 52 m: the long walls get 14/52 of the points each.
  EXPECT_NEAR(per_wall[0], 500 * 14.0 / 52, 40);
  EXPECT_NEAR(per_wall[1], 500 * 12.0 / 52, 40);
  // Reproducible from the seed, different with another.
  EXPECT_EQ(RandomWallLandmarks(500, path, 2.0, 4.0, 9, 36)[77].p_W, pts[77].p_W);
  EXPECT_NE(RandomWallLandmarks(500, path, 2.0, 4.0, 10, 36)[77].p_W, pts[77].p_W);
}

TEST(Landmarks, LayoutSelectsTheSets) {
  const std::vector<Eigen::Vector3d> path = {{0, 0, 0}, {1, 1, 1}};
  LandmarkOptions o;
  EXPECT_EQ(MakeLandmarks(o, path, 1).size(), 36u);
  o.layout = LandmarkLayout::kRandom;
  o.random_count = 10;
  EXPECT_EQ(MakeLandmarks(o, path, 1).size(), 10u);
  EXPECT_EQ(MakeLandmarks(o, path, 1).front().id, 0);
  o.layout = LandmarkLayout::kHouseAndRandom;
  EXPECT_EQ(MakeLandmarks(o, path, 1).size(), 46u);
}

}  // namespace
}  // namespace vigil::sim
