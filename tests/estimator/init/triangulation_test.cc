#include "estimator/init/triangulation.h"

#include <gtest/gtest.h>

#include "synthetic_scene.h"

namespace vigil::estimator {
namespace {

TEST(TriangulateDlt, RecoversPointsFromThreeViews) {
  Rng rng(7, "test_triangulation");
  const auto points = testing::RandomPoints(rng, 50, 3.0, 4.0, 10.0);
  std::vector<Projection> views;
  for (int k = 0; k < 3; ++k) {
    Projection P;
    P << ExpQ(testing::RandomVector(rng, 0.05)).toRotationMatrix(), testing::RandomVector(rng, 0.5);
    views.push_back(P);
  }
  for (const auto& p : points) {
    std::vector<Eigen::Vector2d> obs;
    for (const auto& P : views) obs.push_back(testing::Observe(P.leftCols<3>(), P.col(3), p, rng, 0.0));
    Eigen::Vector3d est;
    ASSERT_TRUE(TriangulateDlt(views, obs, &est));
    EXPECT_LT((est - p).norm(), 1e-9);
    for (const auto& P : views) EXPECT_GT(DepthIn(P, est), 0.0);
  }
}

TEST(TriangulateDlt, NoisyObservationsGiveNearbyPoints) {
  Rng rng(8, "test_triangulation");
  const auto points = testing::RandomPoints(rng, 50, 2.0, 4.0, 6.0);
  Projection P1, P2;
  P1 << Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero();
  P2 << ExpQ(Eigen::Vector3d(0, 0.1, 0)).toRotationMatrix(), Eigen::Vector3d(-1.0, 0, 0);
  double sum_sq = 0.0;
  for (const auto& p : points) {
    Eigen::Vector3d est;
    ASSERT_TRUE(TriangulateDlt({P1, P2},
                               {testing::Observe(P1.leftCols<3>(), P1.col(3), p, rng, 1.0 / 460),
                                testing::Observe(P2.leftCols<3>(), P2.col(3), p, rng, 1.0 / 460)},
                               &est));
    sum_sq += (est - p).squaredNorm();
  }
  // 1 px noise, 1 m baseline at 5 m: depth error ~ z^2 / (b f) ~ 5 cm.
  EXPECT_LT(std::sqrt(sum_sq / points.size()), 0.15);
}

TEST(TriangulateDlt, RejectsTooFewViews) {
  Projection P;
  P << Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero();
  Eigen::Vector3d p;
  EXPECT_FALSE(TriangulateDlt({P}, {Eigen::Vector2d(0.1, 0.2)}, &p));
  EXPECT_FALSE(TriangulateDlt({P, P}, {Eigen::Vector2d(0.1, 0.2)}, &p));
}

}  // namespace
}  // namespace vigil::estimator
