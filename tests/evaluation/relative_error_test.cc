#include "evaluation/relative_error.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/so3.h"

namespace vigil::evaluation {
namespace {

Eigen::Isometry3d Pose(const Eigen::Matrix3d& R, const Eigen::Vector3d& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = p;
  return T;
}

// A straight 100 m path along x at 0.1 m spacing (integers of 0.1 m, so distances are exact multiples).
std::vector<Eigen::Isometry3d> StraightLine() {
  std::vector<Eigen::Isometry3d> T;
  for (int k = 0; k <= 1000; ++k)
    T.push_back(Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(k * 0.1, 0, 0)));
  return T;
}

TEST(RelativeError, PairsAreTheClosestDistanceWithinTolerance) {
  const std::vector<double> d = {0, 1, 2, 2, 2, 5, 9, 10};
  using P = std::pair<std::size_t, std::size_t>;
  // L = 2, tolerance 0.4: only 0 -> 2 (index 2) is close enough.
  EXPECT_EQ(SubTrajectoryPairs(d, 2.0, 0.4), (std::vector<P>{{0, 2}}));
  // L = 4, tolerance 0.8: 1 -> 5 and 5 -> 9 exactly; from 0 the best end (5, error 1) is too far off.
  EXPECT_EQ(SubTrajectoryPairs(d, 4.0, 0.8), (std::vector<P>{{1, 5}, {5, 6}}));
  EXPECT_EQ(SubTrajectoryPairs(d, 4.0, 1.5),
            (std::vector<P>{{0, 5}, {1, 5}, {2, 5}, {3, 5}, {4, 5}, {5, 6}}));
  // Equal errors go to the earlier end: from 0 with L = 1.5, distances 1 and 2 are both 0.5 away.
  EXPECT_EQ(SubTrajectoryPairs(d, 1.5, 0.6).front(), P(0, 1));
  // On a plateau (standing still) the first pose of the plateau is the end: from 1 with L = 1 -> index 2.
  EXPECT_EQ(SubTrajectoryPairs(d, 1.0, 0.2)[1], P(1, 2));
}

TEST(RelativeError, ConstantScaleDriftGivesKnownTranslationError) {
  const auto gt = StraightLine();
  std::vector<Eigen::Isometry3d> est;
  for (const auto& T : gt) est.push_back(Pose(T.linear(), 1.01 * T.translation()));  // 1 % too long
  for (double L : {7.0, 14.0, 35.0}) {
    const RelativeErrors r = ComputeRelativeErrors(est, gt, L);
    // Starts up to 100 m - 0.8 L still find an end (the last pose, within 0.2 L of the target): as rpg.
    ASSERT_EQ(r.trans_m.size(), static_cast<std::size_t>(std::lround((100.0 - 0.8 * L) / 0.1))) << L;
    for (std::size_t k = 0; k < r.trans_m.size(); ++k) {
      const double travelled_m = std::min(L, 100.0 - 0.1 * k);
      EXPECT_NEAR(r.trans_m[k], 0.01 * travelled_m, 1e-9) << L << " " << k;
      EXPECT_NEAR(r.trans_perc[k], travelled_m / L, 1e-7) << L;
      EXPECT_NEAR(r.yaw_deg[k], 0.0, 1e-9);
      EXPECT_NEAR(r.rot_deg[k], 0.0, 1e-6);
    }
  }
  // A sim3 scale of 1 / 1.01 undoes the drift.
  for (double e : ComputeRelativeErrors(est, gt, 7.0, 1.0 / 1.01).trans_m) EXPECT_NEAR(e, 0.0, 1e-9);
}

TEST(RelativeError, ConstantYawDriftGivesKnownYawError) {
  const auto gt = StraightLine();
  const double rate_rad_per_m = 0.2 * M_PI / 180.0;  // 0.2 deg per metre travelled
  std::vector<Eigen::Isometry3d> est;
  for (const auto& T : gt) est.push_back(Pose(RotZ(rate_rad_per_m * T.translation().x()), T.translation()));
  for (double L : {7.0, 21.0}) {
    const RelativeErrors r = ComputeRelativeErrors(est, gt, L);
    ASSERT_FALSE(r.yaw_deg.empty());
    for (std::size_t k = 0; k < r.yaw_deg.size(); ++k) {
      const double travelled_m = std::min(L, 100.0 - 0.1 * k);
      EXPECT_NEAR(r.yaw_deg[k], 0.2 * travelled_m, 1e-7) << L;
      EXPECT_NEAR(r.rot_deg[k], 0.2 * travelled_m, 1e-6) << L;
    }
  }
}

TEST(RelativeError, RigidOffsetOfTheWholeTrajectoryHasNoRelativeError) {
  std::vector<Eigen::Isometry3d> gt, est;
  const Eigen::Isometry3d offset = Pose(ExpQ(Eigen::Vector3d(0.4, -0.2, 1.3)).toRotationMatrix(), {5, -3, 2});
  for (int k = 0; k < 600; ++k) {
    const double t = k / 30.0;
    const Eigen::Vector3d p(15 * std::cos(M_PI / 10 * t), 20 * std::sin(M_PI / 10 * t), std::sin(M_PI * t));
    gt.push_back(Pose(
        ExpQ(Eigen::Vector3d(0.1 * std::cos(t), 0.2 * std::sin(t), M_PI / 10 * t)).toRotationMatrix(), p));
    est.push_back(offset * gt.back());
  }
  const RelativeErrors r = ComputeRelativeErrors(est, gt, 14.0);
  ASSERT_GT(r.trans_m.size(), 100u);
  for (std::size_t k = 0; k < r.trans_m.size(); ++k) {
    EXPECT_NEAR(r.trans_m[k], 0.0, 1e-9);
    EXPECT_NEAR(r.yaw_deg[k], 0.0, 1e-9);
  }
}

TEST(RelativeError, TooShortTrajectoryHasNoSample) {
  const auto gt = StraightLine();  // 100 m: one pair at most for L = 100
  EXPECT_TRUE(ComputeRelativeErrors(gt, gt, 100.0, 1.0, 0.01).trans_m.empty());
  EXPECT_TRUE(ComputeRelativeErrors(gt, gt, 500.0).trans_m.empty());
  EXPECT_THROW(ComputeRelativeErrors(gt, {}, 7.0), std::invalid_argument);
}

}  // namespace
}  // namespace vigil::evaluation
