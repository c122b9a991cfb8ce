// The pose covariance at a rate (EstimatorOptions::covariance_rate_hz): the same estimate, and the same
// covariances where they are computed.
#include <gtest/gtest.h>

#include "estimator/run_estimator.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// Every frame solved, so that the covariance's rate is the only one.
EstimatorResult RunWithCovarianceRate(const EstimatorInput& input, double covariance_rate_hz) {
  EstimatorOptions options;
  options.max_frame_rate_hz = 0.0;
  options.covariance_rate_hz = covariance_rate_hz;
  return RunEstimator(options, input);
}

// A short paper run from a 30 Hz camera: at 10 Hz the first tracked pose and every third one after it have
// a covariance, bit for bit the one computed at every frame, and the others none; the trajectory is the
// same bytes.
TEST(CovarianceRate, EveryThirdPoseOfA30HzCameraGetsTheSameCovariance) {
  const auto [data, input] = testing::SimulatePaperRun(6.0, 5);
  const EstimatorResult every = RunWithCovarianceRate(input, 0.0);
  const EstimatorResult rated = RunWithCovarianceRate(input, 10.0);
  ASSERT_TRUE(every.ok) << every.failure_reason;
  ASSERT_TRUE(rated.ok) << rated.failure_reason;
  EXPECT_EQ(rated.resets, 0);
  ASSERT_EQ(rated.trajectory.size(), every.trajectory.size());
  ASSERT_EQ(rated.pose_covariances.size(), rated.trajectory.size());
  ASSERT_EQ(every.pose_covariances.size(), every.trajectory.size());
  int with_covariance = 0;
  for (std::size_t i = 0; i < rated.trajectory.size(); ++i) {
    EXPECT_EQ(rated.trajectory[i].t_ns, every.trajectory[i].t_ns);
    EXPECT_EQ(rated.trajectory[i].p_W, every.trajectory[i].p_W) << "row " << i;
    EXPECT_EQ(rated.trajectory[i].q_WB.coeffs(), every.trajectory[i].q_WB.coeffs()) << "row " << i;
    ASSERT_TRUE(every.pose_covariances[i].allFinite()) << "row " << i;
    if (i % 3 == 0) {
      EXPECT_EQ(rated.pose_covariances[i], every.pose_covariances[i]) << "row " << i;
      ++with_covariance;
    } else {
      EXPECT_TRUE(rated.pose_covariances[i].array().isNaN().all()) << "row " << i;
    }
  }
  EXPECT_GT(with_covariance, 40);
}

// At the defaults the frame-rate cap and the covariance's rate are both 10 Hz: every pose of the trajectory
// (a solved frame) has its covariance.
TEST(CovarianceRate, AtTheDefaultsEverySolvedPoseHasACovariance) {
  const EstimatorResult result = RunEstimator(EstimatorOptions{}, testing::SimulatePaperRun(6.0, 5).input);
  ASSERT_TRUE(result.ok) << result.failure_reason;
  ASSERT_GT(result.trajectory.size(), 20u);
  ASSERT_EQ(result.pose_covariances.size(), result.trajectory.size());
  for (std::size_t i = 0; i < result.pose_covariances.size(); ++i) {
    EXPECT_TRUE(result.pose_covariances[i].allFinite()) << "row " << i;
  }
}

}  // namespace
}  // namespace vigil::estimator
