// The newest pose's covariance on linear-Gaussian toys with a known answer, and on a short estimator run.
#include "estimator/pose_covariance.h"

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "estimator/pose_manifold.h"
#include "estimator/run_estimator.h"
#include "evaluation/nees.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// Holding a pose's position and yaw is conditioning the Gaussian of information H on those four
// combinations g = A x: the newest block of Sigma - Sigma A^T (A Sigma A^T)^-1 A Sigma, Sigma = H^-1.
TEST(PoseCovariance, HoldingTheGaugeIsConditioningOnPositionAndYaw) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  const int n = 6 + 9 + 6;  // oldest pose, a speed-bias block, newest pose
  Eigen::MatrixXd J(40, n);
  for (int i = 0; i < J.rows(); ++i)
    for (int j = 0; j < n; ++j) J(i, j) = n01(rng);
  const Eigen::MatrixXd H = J.transpose() * J;
  const Eigen::Quaterniond q_oldest(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  const int newest = 15;

  Eigen::MatrixXd held = H;
  AddGaugeInformation(q_oldest, 0, &held);
  Matrix6d fixed;
  ASSERT_TRUE(MarginalPoseCovariance(held, {6, 9, 6}, newest, &fixed));

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

// A window's information: poses coupled to each other (shared features), each speed-bias block to its own
// and its neighbours' states (IMU factors). Eliminating the sparse blocks first gives the dense inverse.
TEST(PoseCovariance, TheBlockEliminationIsTheInverse) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n01;
  const int frames = 12;
  std::vector<int> sizes;
  for (int k = 0; k < frames; ++k) sizes.insert(sizes.end(), {6, 9});
  const int n = frames * 15;
  auto random_information = [&](int rows, int cols) {
    Eigen::MatrixXd J(rows, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) J(i, j) = n01(rng);
    return Eigen::MatrixXd(J.transpose() * J);
  };
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < frames; ++k) H.block(15 * k, 15 * k, 15, 15) += random_information(20, 15);
  for (int k = 1; k < frames; ++k) H.block(15 * (k - 1), 15 * (k - 1), 30, 30) += random_information(15, 30);
  const Eigen::MatrixXd poses = random_information(40, 6 * frames);  // every pose with every pose
  for (int i = 0; i < frames; ++i)
    for (int j = 0; j < frames; ++j) H.block(15 * i, 15 * j, 6, 6) += poses.block(6 * i, 6 * j, 6, 6);
  const Eigen::MatrixXd Sigma = H.inverse();
  for (const int newest : {15 * (frames - 1), 15 * 4, 0}) {
    Matrix6d P;
    ASSERT_TRUE(MarginalPoseCovariance(H, sizes, newest, &P));
    const Matrix6d expected = Sigma.block(newest, newest, 6, 6);
    EXPECT_LT((P - expected).norm(), 1e-9 * expected.norm()) << newest;
  }
  Matrix6d P;
  EXPECT_FALSE(MarginalPoseCovariance(H, sizes, 6, &P)) << "no pose block starts there";
  H.block(15 * 3 + 6, 15 * 3 + 6, 9, 9).setZero();  // a speed-bias block without information of its own
  H.block(15 * 3 + 6, 0, 9, n).setZero();
  H.block(0, 15 * 3 + 6, n, 9).setZero();
  EXPECT_FALSE(MarginalPoseCovariance(H, sizes, 0, &P)) << "not positive definite";
}

TEST(PoseCovariance, AGaugeOnlyMatrixHasNoCovariance) {
  // Information on roll and pitch of one pose only: position and yaw held, the rest (the newest) is free.
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(12, 12);
  H.block(3, 3, 2, 2).setIdentity();
  AddGaugeInformation(Eigen::Quaterniond::Identity(), 0, &H);
  Matrix6d P;
  EXPECT_FALSE(MarginalPoseCovariance(H, {6, 6}, 6, &P));
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

// Every output pose of a short paper run has a finite, positive definite covariance, and the NEES in the
// covariance's gauge is of the order of 3 (measured on this run: 1.81 position, 1.22 orientation with the
// 15-keyframe window; docs/estimator.md): neither absurdly cautious nor overconfident.
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
