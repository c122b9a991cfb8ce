// The newest pose's covariance on linear-Gaussian toys with a known answer, and on a short estimator run.
#include "estimator/pose_covariance.h"

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "estimator/pose_manifold.h"
#include "estimator/run_estimator.h"
#include "estimator/window_factorization.h"
#include "evaluation/nees.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// Holding a pose's position and yaw is conditioning the Gaussian of information H on those four
// combinations g = A x: the newest block of Sigma - Sigma A^T (A Sigma A^T)^-1 A Sigma, Sigma = H^-1.
TEST(PoseCovariance, HoldingTheGaugeIsConditioningOnPositionAndYaw) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  const int n = 2 * 15;  // two frames: oldest pose and speed-bias, newest pose and speed-bias
  Eigen::MatrixXd J(60, n);
  for (int i = 0; i < J.rows(); ++i)
    for (int j = 0; j < n; ++j) J(i, j) = n01(rng);
  const Eigen::MatrixXd H = J.transpose() * J;
  const Eigen::Quaterniond q_oldest(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  const int newest = 15;

  Eigen::MatrixXd held = H;
  AddGaugeInformation(q_oldest, 0, &held);
  WindowFactorization factorization;
  ASSERT_TRUE(factorization.Compute(held));
  const Matrix6d fixed = factorization.NewestPoseCovariance();

  const Eigen::MatrixXd Sigma = H.inverse();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, n);
  A.topLeftCorner(3, 3).setIdentity();
  A.block(3, 3, 1, 3) = Eigen::Vector3d::UnitZ().transpose() * q_oldest.toRotationMatrix();
  const Eigen::MatrixXd conditional =
      Sigma - Sigma * A.transpose() * (A * Sigma * A.transpose()).inverse() * A * Sigma;
  const Matrix6d expected = conditional.block(newest, newest, 6, 6);
  EXPECT_LT((fixed - expected).norm(), 1e-6 * expected.norm()) << fixed << "\n\n" << expected;
  // Conditioning only removes uncertainty.
  EXPECT_LT(fixed.trace(), Sigma.block(newest, newest, 6, 6).trace());
}

TEST(PoseCovariance, AGaugeOnlyMatrixHasNoCovariance) {
  // Information on roll and pitch of one pose only: position and yaw held, the rest is free.
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(30, 30);
  H.block(3, 3, 2, 2).setIdentity();
  AddGaugeInformation(Eigen::Quaterniond::Identity(), 0, &H);
  WindowFactorization factorization;
  EXPECT_FALSE(factorization.Compute(H));
}

// The gauge prior is the same information as AddGaugeInformation, at the pose's value: zero residual there,
// stiff in position and in the yaw about world z, blind to roll and pitch.
TEST(PoseCovariance, TheGaugePriorHoldsPositionAndYawOnly) {
  const Eigen::Quaterniond q_WB(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  double pose[kPoseSize] = {1, 2, 3, q_WB.x(), q_WB.y(), q_WB.z(), q_WB.w()};
  const LinearPrior prior = GaugePrior(pose);
  ASSERT_EQ(prior.blocks.size(), 1u);
  EXPECT_EQ(prior.blocks[0].address, pose);
  EXPECT_EQ(prior.r.norm(), 0.0);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(6, 6);
  AddGaugeInformation(q_WB, 0, &H);
  EXPECT_LT((prior.H - H).norm(), 1e-6);
  EXPECT_LT((prior.J.transpose() * prior.J - prior.H).norm(), 1e-6);
  // Rotated +90 deg about x, the body y axis is world z: a body-y rotation
  // is a yaw, body x and z rotations are roll and pitch.
  Eigen::Matrix<double, 6, 1> yaw = Eigen::Matrix<double, 6, 1>::Zero(), roll = yaw;
  yaw(4) = 1e-3;
  roll(3) = 1e-3;
  EXPECT_NEAR(yaw.dot(prior.H * yaw), kGaugeInformation * 1e-6, 1e-3);
  EXPECT_NEAR(roll.dot(prior.H * roll), 0.0, 1e-9);
}

// With the covariance at every frame, every output pose of a short paper run has a finite, positive
// definite covariance, and the NEES in the covariance's gauge is of the order of 3 (measured on this run:
// 1.81 position, 1.22 orientation with the 15-keyframe window; docs/estimator.md): neither absurdly
// cautious nor overconfident.
TEST(PoseCovariance, EveryOutputPoseOfARunHasACovariance) {
  const auto [data, input] = testing::SimulatePaperRun(8.0, 4);
  EstimatorOptions options;
  options.covariance_rate_hz = 0.0;
  const EstimatorResult result = RunEstimator(options, input);
  ASSERT_TRUE(result.ok) << result.failure_reason;
  ASSERT_EQ(result.pose_covariances.size(), result.trajectory.size());
  for (const Matrix6d& P : result.pose_covariances) {
    ASSERT_TRUE(P.allFinite());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix6d>(P).eigenvalues().minCoeff(), 0.0);
  }
  Trajectory gt;
  for (const StampedPose& pose : result.trajectory) {
    NavState truth;
    ASSERT_TRUE(InterpolateNavState(data.groundtruth, pose.t_ns, &truth));
    gt.push_back({pose.t_ns, truth.p_W, truth.q_WB});
  }
  const evaluation::NeesStatistics nees =
      evaluation::ComputeNees(gt, result.trajectory, result.pose_covariances,
                              evaluation::GaugeAlignment(gt, result.trajectory, result.pose_covariances));
  std::printf("NEES position %.2f orientation %.2f over %lld poses, covariance %.3f s of optimize %.3f s\n",
              nees.position.mean, nees.orientation.mean, static_cast<long long>(nees.position.n),
              result.timing.covariance_s, result.timing.optimize_s);
  EXPECT_EQ(nees.position.n, static_cast<long long>(result.trajectory.size()));
  EXPECT_GT(nees.position.mean, 0.3);
  EXPECT_LT(nees.position.mean, 10.0);
  EXPECT_GT(nees.orientation.mean, 0.3);
  EXPECT_LT(nees.orientation.mean, 10.0);
}

}  // namespace
}  // namespace vigil::estimator
