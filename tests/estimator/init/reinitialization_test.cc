// End to end: `estimator.init: vins` starts from nothing, and after an extreme IMU glitch burst the failure
// detection resets the estimator, which re-initializes and tracks again.
#include <limits>

#include <gtest/gtest.h>

#include "core/interpolation.h"
#include "estimator/run_estimator.h"
#include "sim/simulator.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

struct TrackingErrors {
  double max_speed_error_mps =
      0.0;  // | |v_est| - |v_true| |, independent of the unobservable yaw and position
  double max_tilt_error_deg = 0.0;  // angle between estimated and true gravity direction in the body frame
  int states = 0;
};

TrackingErrors ErrorsBetween(const EstimatorResult& result, const std::vector<NavState>& groundtruth,
                             int64_t from_ns, int64_t to_ns) {
  TrackingErrors e;
  for (const NavState& s : result.states) {
    NavState truth;
    if (s.t_ns < from_ns || s.t_ns >= to_ns || !InterpolateNavState(groundtruth, s.t_ns, &truth)) continue;
    ++e.states;
    e.max_speed_error_mps = std::max(e.max_speed_error_mps, std::abs(s.v_W.norm() - truth.v_W.norm()));
    const Eigen::Vector3d down_est = s.q_WB.conjugate() * -Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d down_true = truth.q_WB.conjugate() * -Eigen::Vector3d::UnitZ();
    e.max_tilt_error_deg =
        std::max(e.max_tilt_error_deg, std::acos(std::min(1.0, down_est.dot(down_true))) * 180.0 / M_PI);
  }
  return e;
}

// Every frame solved, and 10 of the camera's 30 per second (estimator.max_frame_rate_hz). At 10 the reset
// fires a frame earlier, inside the burst, and the window after it starts inside the burst too: vigil's
// gyroscope check (vins.max_gyro_residual_deg) keeps the initializer from taking it.
class VinsReinitialization : public ::testing::TestWithParam<double> {};

TEST_P(VinsReinitialization, ExtremeGlitchBurstResetsAndTheRunRecovers) {
  sim::SimOptions sim_options;
  sim_options.duration_s = 8.0;
  constexpr uint64_t kSeed = 5;
  Dataset data = sim::Simulate(sim_options, kSeed);
  // 0.25 s of +200 m/s^2 on a_z and +10 rad/s on w_z from t = 3 s: far beyond what the window can explain.
  const int64_t burst_begin_ns = SToNs(3.0), burst_end_ns = SToNs(3.25);
  for (ImuSample& s : data.imu) {
    if (s.t_ns < burst_begin_ns || s.t_ns >= burst_end_ns) continue;
    s.a_B.z() += 200.0;
    s.w_B.z() += 10.0;
  }
  EstimatorInput input = testing::InputFromSimulation(sim_options, data, kSeed);
  input.groundtruth.clear();  // vins must not need it
  EstimatorOptions options;
  options.init = InitMode::kVins;
  // The 10-keyframe window at 10 px the bounds below were set with: with the default 15 keyframes at 20 px
  // the re-initialized window is not yet settled 1.5 s after this burst (tilt error about 11 deg).
  options.window.size = 10;
  options.window.min_parallax_px = 10.0;
  options.max_frame_rate_hz = GetParam();
  const EstimatorResult result = RunEstimator(options, input);

  ASSERT_TRUE(result.ok) << result.failure_reason;
  EXPECT_LT(result.initialized_at_s, NsToS(data.frames.front().t_ns) + 2.0);
  EXPECT_GE(result.resets, 1);
  ASSERT_FALSE(result.states.empty());
  // The trajectory continues to the end of the recording.
  EXPECT_GT(NsToS(result.states.back().t_ns), sim_options.duration_s - 0.2);
  // From 1 s after the initialization to the burst, and from 1.5 s after it, the estimate tracks speed and
  // attitude.
  const TrackingErrors before =
      ErrorsBetween(result, data.groundtruth, SToNs(result.initialized_at_s + 1.0), burst_begin_ns);
  const TrackingErrors after =
      ErrorsBetween(result, data.groundtruth, burst_end_ns + SToNs(1.5), std::numeric_limits<int64_t>::max());
  // Each interval has (nearly) a state per solved frame: 30 or 10 per second.
  const double rate_hz = GetParam() > 0.0 ? GetParam() : 30.0;
  const double before_s = NsToS(burst_begin_ns) - result.initialized_at_s - 1.0;
  const double after_s = sim_options.duration_s - NsToS(burst_end_ns) - 1.5;
  EXPECT_GT(before_s, 0.5);
  EXPECT_GE(before.states, static_cast<int>(0.9 * before_s * rate_hz));
  EXPECT_LT(before.max_speed_error_mps, 0.3);
  EXPECT_LT(before.max_tilt_error_deg, 2.0);
  EXPECT_GE(after.states, static_cast<int>(0.9 * after_s * rate_hz));
  EXPECT_LT(after.max_speed_error_mps, 0.3);
  EXPECT_LT(after.max_tilt_error_deg, 2.0);
}

INSTANTIATE_TEST_SUITE_P(FramesSolved, VinsReinitialization, ::testing::Values(0.0, 10.0));

}  // namespace
}  // namespace vigil::estimator
