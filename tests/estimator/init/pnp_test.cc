#include "estimator/init/pnp.h"

#include <gtest/gtest.h>

#include "synthetic_scene.h"

namespace vigil::estimator {
namespace {

TEST(PnpResidual, JacobianMatchesFiniteDifferences) {
  Rng rng(3, "test_pnp");
  const Eigen::Matrix3d R = ExpQ(testing::RandomVector(rng, 0.3)).toRotationMatrix();
  const Eigen::Vector3d p(0.2, -0.1, 0.3), p_X(0.5, -0.4, 5.0);
  const Eigen::Vector2d obs(0.01, -0.02);
  Eigen::Matrix<double, 2, 6> J;
  PnpResidual(R, p, p_X, obs, &J);
  const double h = 1e-6;
  for (int k = 0; k < 6; ++k) {
    Eigen::Matrix<double, 6, 1> d = Eigen::Matrix<double, 6, 1>::Zero();
    d[k] = h;
    auto at = [&](double sign) {
      const Eigen::Matrix3d Rk = ExpQ(sign * d.head<3>()).toRotationMatrix() * R;
      return PnpResidual(Rk, p + sign * d.tail<3>(), p_X, obs, nullptr);
    };
    const Eigen::Vector2d numeric = (at(1) - at(-1)) / (2 * h);
    EXPECT_LT((numeric - J.col(k)).norm(), 1e-7) << "column " << k;
  }
}

TEST(SolvePnp, RecoversThePoseFromAPerturbedGuess) {
  Rng rng(4, "test_pnp");
  const auto points = testing::RandomPoints(rng, 30, 3.0, 4.0, 9.0);
  const Eigen::Matrix3d R_true = ExpQ(Eigen::Vector3d(0.05, -0.1, 0.2)).toRotationMatrix();
  const Eigen::Vector3d p_true(0.3, -0.2, 0.5);
  std::vector<Eigen::Vector2d> obs;
  for (const auto& p : points) obs.push_back(testing::Observe(R_true, p_true, p, rng, 0.0));
  Eigen::Matrix3d R = ExpQ(Eigen::Vector3d(0.1, 0.05, 0.1)).toRotationMatrix() * R_true;
  Eigen::Vector3d p = p_true + Eigen::Vector3d(0.3, 0.2, -0.3);
  ASSERT_TRUE(SolvePnp(points, obs, PnpOptions{}, &R, &p));
  EXPECT_LT(testing::RotationErrorRad(R, R_true), 1e-8);
  EXPECT_LT((p - p_true).norm(), 1e-8);
}

TEST(SolvePnp, NoisyPixelsGiveACloseEstimate) {
  Rng rng(5, "test_pnp");
  const auto points = testing::RandomPoints(rng, 40, 3.0, 4.0, 9.0);
  const Eigen::Matrix3d R_true = ExpQ(Eigen::Vector3d(-0.1, 0.2, 0.05)).toRotationMatrix();
  const Eigen::Vector3d p_true(-0.3, 0.1, 0.2);
  std::vector<Eigen::Vector2d> obs;
  for (const auto& p : points) obs.push_back(testing::Observe(R_true, p_true, p, rng, 1.0 / 460));
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  ASSERT_TRUE(SolvePnp(points, obs, PnpOptions{}, &R, &p));
  EXPECT_LT(testing::RotationErrorRad(R, R_true), 0.01);
  EXPECT_LT((p - p_true).norm(), 0.05);
}

TEST(SolvePnp, RejectsTooFewPoints) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  EXPECT_FALSE(
      SolvePnp({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}}, {{0, 0}, {0.2, 0}, {0, 0.2}}, PnpOptions{}, &R, &p));
}

}  // namespace
}  // namespace vigil::estimator
