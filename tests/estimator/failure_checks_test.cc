// The estimator's checks of its own state (FailureOptions): each check fires on a run built to trip it and
// stays quiet on a clean run; a fired check stops a run that cannot re-initialize, and is counted by name.
#include <cstdint>

#include <gtest/gtest.h>

#include "estimator/run_estimator.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

constexpr int64_t kOneSecondNs = 1'000'000'000;

// The run stopped on `check`, once, and nothing else fired.
void ExpectStoppedBy(const EstimatorResult& result, const std::string& check) {
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.stops, 1);
  EXPECT_EQ(result.resets, 0);
  ASSERT_EQ(result.failure_checks.size(), 1u) << result.failure_reason;
  EXPECT_EQ(result.failure_checks.begin()->first, check) << result.failure_reason;
  EXPECT_EQ(result.failure_checks.begin()->second, 1);
}

TEST(FailureChecksTest, CleanRunTripsNoCheck) {
  const EstimatorResult result = RunEstimator(EstimatorOptions{}, testing::SimulatePaperRun(4.0, 11).input);
  ASSERT_TRUE(result.ok) << result.failure_reason;
  EXPECT_EQ(result.stops, 0);
  EXPECT_TRUE(result.failure_checks.empty());
}

// A gyroscope whose bias runs away (0.05 rad/s more every second from t = 1 s, on every axis) is tracked by
// the window; the bias norm check stops the run once the estimate passes the bound, and not before.
TEST(FailureChecksTest, GyroBiasRunawayTripsTheBiasCheck) {
  EstimatorInput input = testing::SimulatePaperRun(8.0, 12).input;
  for (ImuSample& s : input.imu) {
    const double t_s = static_cast<double>(s.t_ns - input.imu.front().t_ns) / kOneSecondNs;
    if (t_s > 1.0) s.w_B += Eigen::Vector3d::Constant(0.05 * (t_s - 1.0));
  }
  EstimatorOptions options;
  options.failure.max_gyro_bias = 0.2;  // reached near t = 3.3 s by the true bias (norm 0.087 / s)
  const EstimatorResult result = RunEstimator(options, input);
  ExpectStoppedBy(result, "gyro_bias");
  EXPECT_NE(result.failure_reason.find("gyro bias norm"), std::string::npos) << result.failure_reason;
  ASSERT_FALSE(result.states.empty());
  EXPECT_GT(result.states.back().b_g.norm(), 0.1);  // it stopped late in the runaway, not on noise
}

// The paper's ellipse runs at several m/s: a speed bound below that trips the speed check.
TEST(FailureChecksTest, SpeedAboveTheBoundTripsTheSpeedCheck) {
  EstimatorOptions options;
  options.failure.max_speed_mps = 0.5;
  ExpectStoppedBy(RunEstimator(options, testing::SimulatePaperRun(3.0, 13).input), "speed");
}

// From t = 2 s the camera sees nothing: after max_lost_frames frames without tracks the run stops.
TEST(FailureChecksTest, LosingEveryTrackTripsTheTrackCheck) {
  EstimatorInput input = testing::SimulatePaperRun(4.0, 14).input;
  const int64_t blind_from_ns = input.frames.front().t_ns + 2 * kOneSecondNs;
  int blind_frames = 0;
  for (CameraFrame& frame : input.frames)
    if (frame.t_ns >= blind_from_ns) {
      frame.features.clear();
      ++blind_frames;
    }
  EstimatorOptions options;
  options.failure.max_lost_frames = 10;
  ASSERT_GT(blind_frames, options.failure.max_lost_frames);
  const EstimatorResult result = RunEstimator(options, input);
  ExpectStoppedBy(result, "lost_tracks");
  ASSERT_FALSE(result.states.empty());
  // Stopped on the tenth blind frame: the states end nine blind frames after the last seeing one.
  EXPECT_LT(result.states.back().t_ns, blind_from_ns + kOneSecondNs);
}

}  // namespace
}  // namespace vigil::estimator
