// NEES against a known covariance: errors drawn from N(0, P) and normalized by the same P have a mean NEES of
// 3 per 3-DoF block (chi-square with 3 degrees of freedom); normalized by 2 P, 1.5.
#include "evaluation/nees.h"

#include <cmath>
#include <random>

#include <Eigen/Cholesky>

#include <gtest/gtest.h>

#include "core/so3.h"

namespace vigil::evaluation {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// A fixed, correlated covariance: 2-5 cm in position, 0.2-0.6 deg in orientation.
Matrix6d KnownNeesCovariance() {
  Matrix6d L = Matrix6d::Zero();
  L.diagonal() << 0.05, 0.03, 0.02, 0.010, 0.006, 0.004;
  L(1, 0) = 0.02;
  L(2, 1) = -0.01;
  L(4, 3) = 0.003;
  L(5, 0) = 0.002;
  return L * L.transpose();
}

struct NeesSample {
  Trajectory gt, est;
};

// A circle of 4000 poses; the estimate is the truth moved by an error drawn from N(0, P) in the tangent
// [delta p_W, delta theta_B] (est = truth - e_p, R_est = R_gt Exp(-e_theta)).
NeesSample DrawNeesSample(const Matrix6d& P, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01;
  const Eigen::LLT<Matrix6d> llt(P);
  const Matrix6d L = llt.matrixL();
  NeesSample run;
  for (int k = 0; k < 4000; ++k) {
    const double a = 0.01 * k;
    StampedPose g{k * 50'000'000LL, Eigen::Vector3d(10 * std::cos(a), 10 * std::sin(a), 1.0),
                  Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()))};
    Eigen::Matrix<double, 6, 1> z;
    for (int i = 0; i < 6; ++i) z(i) = n01(rng);
    const Eigen::Matrix<double, 6, 1> e = L * z;
    StampedPose e_pose = g;
    e_pose.p_W -= e.head<3>();
    e_pose.q_WB = (g.q_WB * ExpQ(-e.tail<3>())).normalized();
    run.gt.push_back(g);
    run.est.push_back(e_pose);
  }
  return run;
}

TEST(Nees, MeanIsThreeForTheTrueCovariance) {
  const Matrix6d P = KnownNeesCovariance();
  const NeesSample run = DrawNeesSample(P, 1);
  const NeesStatistics nees = ComputeNees(run.gt, run.est, std::vector<Matrix6d>(run.est.size(), P), {});
  ASSERT_EQ(nees.position.n, 4000);
  // The mean of 4000 chi-square(3) draws: std sqrt(6 / 4000) = 0.04.
  EXPECT_NEAR(nees.position.mean, 3.0, 0.16);
  EXPECT_NEAR(nees.orientation.mean, 3.0, 0.16);
  // Too large a covariance (an overcautious estimator) gives a NEES below 3, too small one above it.
  const NeesStatistics cautious =
      ComputeNees(run.gt, run.est, std::vector<Matrix6d>(run.est.size(), 2.0 * P), {});
  EXPECT_NEAR(cautious.position.mean, 1.5, 0.08);
  EXPECT_NEAR(cautious.orientation.mean, 1.5, 0.08);
  const NeesStatistics confident =
      ComputeNees(run.gt, run.est, std::vector<Matrix6d>(run.est.size(), 0.25 * P), {});
  EXPECT_NEAR(confident.position.mean, 12.0, 0.64);
}

// The ground truth in another frame (yawed by 40 deg and shifted): brought into the estimate's frame by the
// inverse of the alignment, the NEES is that of the same errors in one frame.
TEST(Nees, GroundTruthIsBroughtIntoTheEstimateFrame) {
  const Matrix6d P = KnownNeesCovariance();
  const NeesSample run = DrawNeesSample(P, 2);
  SimilarityTransform est_to_gt;
  est_to_gt.R = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  est_to_gt.t = Eigen::Vector3d(3.0, -2.0, 0.5);
  Trajectory moved = run.gt;
  for (StampedPose& g : moved) {
    g.p_W = est_to_gt.Apply(g.p_W);
    g.q_WB = est_to_gt.Rotate(g.q_WB);
  }
  const std::vector<Matrix6d> covariances(run.est.size(), P);
  const NeesStatistics same_frame = ComputeNees(run.gt, run.est, covariances, {});
  const NeesStatistics aligned = ComputeNees(moved, run.est, covariances, est_to_gt);
  EXPECT_NEAR(aligned.position.mean, same_frame.position.mean, 1e-9);
  EXPECT_NEAR(aligned.orientation.mean, same_frame.orientation.mean, 1e-9);
  // Without the alignment the 3 m offset is far outside a few centimetres.
  EXPECT_GT(ComputeNees(moved, run.est, covariances, {}).position.mean, 1000.0);
}

// The covariance's gauge is the first pose: GaugeAlignment maps the estimate's first usable pose onto the
// ground truth in position and yaw, whatever the other poses do.
TEST(Nees, TheGaugeAlignmentHoldsTheFirstPose) {
  const Matrix6d P = KnownNeesCovariance();
  NeesSample run = DrawNeesSample(P, 4);
  SimilarityTransform est_to_gt;
  est_to_gt.R = Eigen::AngleAxisd(-1.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  est_to_gt.t = Eigen::Vector3d(-4.0, 1.0, 2.0);
  std::vector<Matrix6d> covariances(run.est.size(), P);
  covariances[0] = Matrix6d::Constant(std::nan(""));  // the first pose has no covariance: the second holds
  run.est[1] = run.gt[1];
  Trajectory moved = run.gt;
  for (StampedPose& g : moved) {
    g.p_W = est_to_gt.Apply(g.p_W);
    g.q_WB = est_to_gt.Rotate(g.q_WB);
  }
  const SimilarityTransform gauge = GaugeAlignment(moved, run.est, covariances);
  EXPECT_LT((gauge.R - est_to_gt.R).norm(), 1e-9);
  EXPECT_LT((gauge.t - est_to_gt.t).norm(), 1e-9);
  EXPECT_EQ(gauge.scale, 1.0);
  // A roll of the first pose's estimate is not a gauge direction: the yaw stays that of the ground truth.
  run.est[1].q_WB = run.est[1].q_WB * Eigen::Quaterniond(Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()));
  EXPECT_LT((GaugeAlignment(moved, run.est, covariances).R - est_to_gt.R).norm(), 0.01);
  EXPECT_TRUE(GaugeAlignment(moved, run.est, {}).R.isIdentity());  // no covariances: the identity
}

TEST(Nees, PosesWithoutAUsableCovarianceAreSkipped) {
  const Matrix6d P = KnownNeesCovariance();
  const NeesSample run = DrawNeesSample(P, 3);
  std::vector<Matrix6d> covariances(run.est.size(), P);
  covariances[0] = Matrix6d::Constant(std::nan(""));
  covariances[1] = -P;
  EXPECT_EQ(ComputeNees(run.gt, run.est, covariances, {}).position.n, 3998);
  EXPECT_EQ(ComputeNees(run.gt, run.est, {}, {}).position.n, 0);  // no covariances: nothing
}

}  // namespace
}  // namespace vigil::evaluation
