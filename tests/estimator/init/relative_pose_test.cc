#include "estimator/init/relative_pose.h"

#include <gtest/gtest.h>
#include <Eigen/SVD>

#include "synthetic_scene.h"

namespace vigil::estimator {
namespace {

struct TwoViews {
  Eigen::Matrix3d R_21;
  Eigen::Vector3d t_21;
  std::vector<Eigen::Vector2d> x1, x2;
};

TwoViews MakeTwoViews(uint64_t seed, int count, double noise) {
  Rng rng(seed, "test_relative_pose");
  TwoViews v;
  v.R_21 = ExpQ(Eigen::Vector3d(0.02, -0.15, 0.05)).toRotationMatrix();
  v.t_21 = Eigen::Vector3d(-0.8, 0.1, 0.2);
  for (const auto& p : testing::RandomPoints(rng, count, 3.0, 4.0, 10.0)) {
    v.x1.push_back(testing::Observe(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), p, rng, noise));
    v.x2.push_back(testing::Observe(v.R_21, v.t_21, p, rng, noise));
  }
  return v;
}

TEST(EssentialEightPoint, SatisfiesTheEpipolarConstraintAndIsEssential) {
  const TwoViews v = MakeTwoViews(1, 30, 0.0);
  Eigen::Matrix3d E;
  ASSERT_TRUE(EssentialEightPoint(v.x1, v.x2, &E));
  for (std::size_t i = 0; i < v.x1.size(); ++i) EXPECT_LT(SampsonDistance(E, v.x1[i], v.x2[i]), 1e-10);
  const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(E).singularValues();
  EXPECT_NEAR(s[0], s[1], 1e-9);
  EXPECT_NEAR(s[2], 0.0, 1e-9);
  // Proportional to [t]x R.
  const Eigen::Matrix3d E_true = Skew(v.t_21.normalized()) * v.R_21;
  const double sign = E.cwiseProduct(E_true).sum() > 0 ? 1.0 : -1.0;
  EXPECT_LT((sign * E / E.norm() - E_true / E_true.norm()).norm(), 1e-8);
}

TEST(EstimateRelativePose, RecoversRotationAndTranslationDirection) {
  const TwoViews v = MakeTwoViews(2, 40, 0.5 / 460);
  RelativePose pose;
  ASSERT_TRUE(EstimateRelativePose(v.x1, v.x2, RelativePoseOptions{}, &pose));
  // 0.5 px noise, 0.8 m baseline at 4-10 m: a few tenths of a degree of rotation, a few degrees of direction.
  EXPECT_LT(testing::RotationErrorRad(pose.R_21, v.R_21), 0.5 * M_PI / 180);
  EXPECT_NEAR(pose.t_21.norm(), 1.0, 1e-9);
  EXPECT_GT(pose.t_21.dot(v.t_21.normalized()), std::cos(3.0 * M_PI / 180));
  EXPECT_GE(pose.num_inliers, 38);
}

TEST(EstimateRelativePose, RansacRejectsOutliers) {
  TwoViews v = MakeTwoViews(3, 60, 0.3 / 460);
  Rng rng(4, "test_outliers");
  std::vector<bool> is_outlier(v.x1.size(), false);
  for (std::size_t i = 0; i < v.x1.size(); i += 4) {  // 25 % gross mismatches
    v.x2[i] += Eigen::Vector2d(rng.Uniform(-0.2, 0.2), rng.Uniform(-0.2, 0.2));
    is_outlier[i] = true;
  }
  RelativePose pose;
  ASSERT_TRUE(EstimateRelativePose(v.x1, v.x2, RelativePoseOptions{}, &pose));
  EXPECT_LT(testing::RotationErrorRad(pose.R_21, v.R_21), 0.5 * M_PI / 180);
  EXPECT_GT(pose.t_21.dot(v.t_21.normalized()), std::cos(3.0 * M_PI / 180));
  int flagged_outliers = 0;
  for (std::size_t i = 0; i < v.x1.size(); ++i) flagged_outliers += is_outlier[i] && pose.inliers[i];
  EXPECT_LE(flagged_outliers, 1);
  // Deterministic for a given seed.
  RelativePose again;
  ASSERT_TRUE(EstimateRelativePose(v.x1, v.x2, RelativePoseOptions{}, &again));
  EXPECT_EQ(again.inliers, pose.inliers);
}

TEST(EstimateRelativePose, ExactDataGivesTheExactPose) {
  const TwoViews v = MakeTwoViews(6, 25, 0.0);
  RelativePose pose;
  ASSERT_TRUE(EstimateRelativePose(v.x1, v.x2, RelativePoseOptions{}, &pose));
  EXPECT_LT(testing::RotationErrorRad(pose.R_21, v.R_21), 1e-8);
  EXPECT_LT((pose.t_21 - v.t_21.normalized()).norm(), 1e-8);
  EXPECT_EQ(pose.num_inliers, 25);
}

TEST(EstimateRelativePose, FailsWithTooFewPoints) {
  const TwoViews v = MakeTwoViews(5, 7, 0.0);
  RelativePose pose;
  EXPECT_FALSE(EstimateRelativePose(v.x1, v.x2, RelativePoseOptions{}, &pose));
}

}  // namespace
}  // namespace vigil::estimator
