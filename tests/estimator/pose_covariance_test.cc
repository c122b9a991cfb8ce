// The newest pose's covariance on linear-Gaussian toys with a known answer, and on a short estimator run.
#include "estimator/pose_covariance.h"

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "estimator/run_estimator.h"
#include "evaluation/nees.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// Holding the oldest pose's position and yaw is conditioning the Gaussian of information H on those four
// combinations g = A x: the newest block of Sigma - Sigma A^T (A Sigma A^T)^-1 A Sigma, Sigma = H^-1.
TEST(PoseCovariance, GaugeFixingIsConditioningOnPositionAndYaw) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  const int n = 6 + 9 + 6;  // oldest pose, a speed-bias block, newest pose
  Eigen::MatrixXd J(40, n);
  for (int i = 0; i < J.rows(); ++i)
    for (int j = 0; j < n; ++j) J(i, j) = n01(rng);
  const Eigen::MatrixXd H = J.transpose() * J;
  const Eigen::Quaterniond q_oldest(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  const int newest = 15;

  Matrix6d fixed;
  ASSERT_TRUE(GaugeFixedCovariance(H, 0, q_oldest, newest, &fixed));

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
  // Information on roll and pitch of one pose only: position and yaw held, the rest (the newest) is free.
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(12, 12);
  H.block(3, 3, 2, 2).setIdentity();
  Matrix6d P;
  EXPECT_FALSE(GaugeFixedCovariance(H, 0, Eigen::Quaterniond::Identity(), 6, &P));
}

// The oldest frame's yaw uncertainty (std 0.01 rad) moves a newest frame 10 m further along x by 0.1 m
// along y, and turns it by the same yaw; its position uncertainty passes through unchanged.
TEST(PoseCovariance, ChainingAddsTheOldestFramesGaugeUncertainty) {
  Matrix6d oldest = Matrix6d::Zero();
  oldest.topLeftCorner<3, 3>() = 1e-4 * Eigen::Matrix3d::Identity();  // 1 cm per axis
  oldest(5, 5) = 1e-4;                                                // body z = world z here
  oldest(3, 3) = 4.0;                                                 // roll: not a gauge direction, ignored
  const Matrix6d relative = 1e-6 * Matrix6d::Identity();
  const Eigen::Quaterniond q_newest(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  const Matrix6d P =
      ChainGaugeCovariance(relative, oldest, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(),
                           Eigen::Vector3d(10, 0, 0), q_newest);
  EXPECT_NEAR(P(0, 0), 1e-6 + 1e-4, 1e-12);
  EXPECT_NEAR(P(1, 1), 1e-6 + 1e-4 + 100 * 1e-4, 1e-12);
  EXPECT_NEAR(P(2, 2), 1e-6 + 1e-4, 1e-12);
  // World z is the newest body's y axis (rotated +90 deg about x): the yaw appears there.
  EXPECT_NEAR(P(4, 4), 1e-6 + 1e-4, 1e-12);
  EXPECT_NEAR(P(3, 3), 1e-6, 1e-12);
  EXPECT_NEAR(P(5, 5), 1e-6, 1e-12);
  EXPECT_NEAR(P(1, 4), 10 * 1e-4, 1e-12);  // the y shift and the yaw are one and the same draw
}

// Every output pose of a short paper run has a finite, positive definite covariance. The errors are smaller
// than it predicts (measured: mean NEES 0.12 position, 0.69 orientation on this run; docs/estimator.md): the
// covariance is conservative, never overconfident, and not absurdly large either.
TEST(PoseCovariance, EveryOutputPoseOfARunHasACovariance) {
  sim::SimOptions sim_options;
  sim_options.duration_s = 8.0;
  const Dataset data = sim::Simulate(sim_options, 4);
  const EstimatorInput input = testing::InputFromSimulation(sim_options, data, 4);
  const EstimatorResult result = RunEstimator(EstimatorOptions{}, input);
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
  const evaluation::TrajectoryEvaluation ev =
      evaluation::EvaluateTrajectory(gt, result.trajectory, evaluation::EvaluationOptions{});
  const evaluation::NeesStatistics nees =
      evaluation::ComputeNees(gt, result.trajectory, result.pose_covariances, ev.alignment);
  std::printf("NEES position %.2f orientation %.2f over %lld poses, covariance %.3f s of optimize %.3f s\n",
              nees.position.mean, nees.orientation.mean, static_cast<long long>(nees.position.n),
              result.timing.covariance_s, result.timing.optimize_s);
  EXPECT_EQ(nees.position.n, static_cast<long long>(result.trajectory.size()));
  EXPECT_GT(nees.position.mean, 0.03);
  EXPECT_LT(nees.position.mean, 3.0);
  EXPECT_GT(nees.orientation.mean, 0.1);
  EXPECT_LT(nees.orientation.mean, 3.0);
}

}  // namespace
}  // namespace vigil::estimator
