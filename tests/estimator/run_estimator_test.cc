#include "estimator/run_estimator.h"

#include <utility>

#include <gtest/gtest.h>

#include "core/error.h"

#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

TEST(RunEstimatorTest, ShortPaperRunIsAccurate) {
  const auto [data, input] = testing::SimulatePaperRun(5.0, 1);
  const EstimatorResult result = RunEstimator(EstimatorOptions{}, input);
  ASSERT_TRUE(result.ok) << result.failure_reason;
  // One state per solved frame (every third, at the default 10 of the camera's 30 per second) once the first
  // full window (size + 1 solved frames) is initialized.
  EXPECT_EQ(result.solved_frames, static_cast<int>((data.frames.size() + 2) / 3));
  EXPECT_EQ(result.states.size(), result.solved_frames - EstimatorOptions{}.window.size);
  const double ate = testing::PosYawAteRmse(result.states, data.groundtruth);
  std::printf("ATE %.4f m, frames %d keyframes %d, optimize %.3f s marginalize %.3f s\n", ate, result.frames,
              result.keyframes, result.timing.optimize_s, result.timing.marginalize_s);
  EXPECT_LT(ate, 0.1);
}

TEST(RunEstimatorTest, SameInputGivesTheSameOutputBitForBit) {
  // The first window at 10 solved frames per second ends at 1.5 s.
  const auto [data, input] = testing::SimulatePaperRun(2.5, 2);
  const EstimatorResult a = RunEstimator(EstimatorOptions{}, input);
  const EstimatorResult b = RunEstimator(EstimatorOptions{}, input);
  ASSERT_TRUE(a.ok);
  ASSERT_EQ(a.states.size(), b.states.size());
  for (std::size_t i = 0; i < a.states.size(); ++i) {
    EXPECT_EQ(a.states[i].p_W, b.states[i].p_W);
    EXPECT_EQ(a.states[i].q_WB.coeffs(), b.states[i].q_WB.coeffs());
    EXPECT_EQ(a.states[i].b_a, b.states[i].b_a);
  }
}

// A grossly corrupted IMU (a 1000 m/s^2 offset for half a second) makes the estimator diverge; with
// ground-truth initialization it cannot recover, so the run ends as failed with a reason, and no NaN reaches
// the output.
TEST(RunEstimatorTest, DivergenceEndsTheRunWithAReason) {
  auto [data, input] = testing::SimulatePaperRun(3.0, 3);
  for (ImuSample& s : input.imu)
    if (s.t_ns > 1'000'000'000 && s.t_ns < 1'500'000'000) s.a_B.z() += 1000.0;
  const EstimatorResult result = RunEstimator(EstimatorOptions{}, input);
  EXPECT_FALSE(result.ok);
  EXPECT_FALSE(result.failure_reason.empty());
  EXPECT_EQ(result.resets, 0);
  EXPECT_LT(result.states.size(), data.frames.size());
  for (const NavState& s : result.states) {
    EXPECT_TRUE(s.p_W.allFinite());
    EXPECT_TRUE(s.q_WB.coeffs().allFinite());
  }
}

TEST(RunEstimatorTest, RejectsInconsistentInput) {
  auto [data, input] = testing::SimulatePaperRun(1.0, 4);
  EstimatorInput no_truth = input;
  no_truth.groundtruth.clear();
  EXPECT_THROW(RunEstimator(EstimatorOptions{}, no_truth), InputError);
  EstimatorInput unordered = input;
  std::swap(unordered.frames[3], unordered.frames[4]);
  EXPECT_THROW(RunEstimator(EstimatorOptions{}, unordered), InputError);
}

// Timing faults of a consumer IMU (dropped samples, repeated and jittered timestamps): the estimator drops
// the later of two equal timestamps, integrates the uneven intervals and stays accurate; a timestamp going
// backwards is an input error.
TEST(RunEstimatorTest, TimingFaultsAreHandled) {
  sim::SimOptions sim_options;
  sim_options.duration_s = 5.0;
  sim_options.faults.timing.drop_rate = 0.02;
  sim_options.faults.timing.duplicate_rate = 0.02;
  sim_options.faults.timing.jitter_std_s = 0.0005;
  const Dataset data = sim::Simulate(sim_options, 1);
  int repeated = 0;
  for (std::size_t k = 1; k < data.imu.size(); ++k) repeated += data.imu[k].t_ns == data.imu[k - 1].t_ns;
  ASSERT_GT(repeated, 5);
  const EstimatorInput input = testing::InputFromSimulation(sim_options, data, 1);
  const EstimatorResult result = RunEstimator(EstimatorOptions{}, input);
  ASSERT_TRUE(result.ok) << result.failure_reason;
  EXPECT_EQ(result.mitigation.repeated_timestamps, repeated);
  EXPECT_LT(testing::PosYawAteRmse(result.states, data.groundtruth), 0.1);
  EstimatorInput backwards = input;
  backwards.imu[150].t_ns = backwards.imu[149].t_ns - 1000;
  EXPECT_THROW(RunEstimator(EstimatorOptions{}, backwards), InputError);
}

// Gyro glitches N(5, 1) rad/s on wz: vision pins the rotation, so the IMU factor of a glitched interval
// fails its chi-square gate after the solve; gating inflates it, re-solves and the ATE improves.
TEST(RunEstimatorTest, GatingMitigatesGyroGlitches) {
  sim::SimOptions sim_options;
  sim_options.duration_s = 8.0;
  sim_options.glitch.enabled = true;
  sim_options.glitch.axes = {ImuAxis::kWz};
  sim_options.glitch.mean = 5.0;
  sim_options.glitch.std = 1.0;
  const Dataset data = sim::Simulate(sim_options, 1);
  const EstimatorInput input = testing::InputFromSimulation(sim_options, data, 1);
  const EstimatorResult plain = RunEstimator(EstimatorOptions{}, input);
  EstimatorOptions gated_options;
  gated_options.mitigation.gating.enabled = true;
  const EstimatorResult gated = RunEstimator(gated_options, input);
  ASSERT_TRUE(plain.ok) << plain.failure_reason;
  ASSERT_TRUE(gated.ok) << gated.failure_reason;
  EXPECT_EQ(plain.mitigation.gate_tests, 0);
  EXPECT_GT(gated.mitigation.gated_factors, 0);
  EXPECT_GT(gated.mitigation.gate_tests, gated.mitigation.gated_factors);
  EXPECT_GT(gated.mitigation.gated_resolves, 0);
  const double ate_plain = testing::PosYawAteRmse(plain.states, data.groundtruth);
  const double ate_gated = testing::PosYawAteRmse(gated.states, data.groundtruth);
  std::printf("ATE plain %.4f m, gated %.4f m (%d of %d factors gated)\n", ate_plain, ate_gated,
              gated.mitigation.gated_factors, gated.mitigation.gate_tests);
  EXPECT_LT(ate_gated, ate_plain);
}

// N(50, 10) glitches on az: inflating the samples a perfect detector would flag (the known glitch times)
// lets the estimator discount them; the ATE improves over the unmitigated run.
TEST(RunEstimatorTest, InflationMitigatesFlaggedGlitches) {
  sim::SimOptions sim_options;
  sim_options.duration_s = 8.0;
  sim_options.glitch.enabled = true;
  sim_options.glitch.mean = 50.0;
  sim_options.glitch.std = 10.0;
  const Dataset data = sim::Simulate(sim_options, 1);
  EstimatorInput input = testing::InputFromSimulation(sim_options, data, 1);
  const EstimatorResult plain = RunEstimator(EstimatorOptions{}, input);
  input.imu_flagged.assign(input.imu.size(), 0);
  std::size_t k = 0;
  for (const GlitchRecord& g : data.glitches) {
    while (k < input.imu.size() && input.imu[k].t_ns < g.t_ns) ++k;
    if (k < input.imu.size()) input.imu_flagged[k] = 1;
  }
  // Flags change nothing without a mitigation, unless the frame-rate cap solves the frames after them.
  EstimatorOptions ignore_flags;
  ignore_flags.solve_flagged_frames = false;
  EXPECT_EQ(RunEstimator(ignore_flags, input).states.back().p_W, plain.states.back().p_W);
  EstimatorOptions inflate_options;
  inflate_options.mitigation.inflate.enabled = true;
  const EstimatorResult inflated = RunEstimator(inflate_options, input);
  ASSERT_TRUE(plain.ok) << plain.failure_reason;
  ASSERT_TRUE(inflated.ok) << inflated.failure_reason;
  EXPECT_GT(inflated.mitigation.inflated_samples, 0);
  const double ate_plain = testing::PosYawAteRmse(plain.states, data.groundtruth);
  const double ate_inflated = testing::PosYawAteRmse(inflated.states, data.groundtruth);
  std::printf("ATE plain %.4f m, inflated %.4f m\n", ate_plain, ate_inflated);
  EXPECT_LT(ate_inflated, 0.7 * ate_plain);
}

}  // namespace
}  // namespace vigil::estimator

namespace vigil::estimator {
namespace {

// The first corner of the rescue course (configs/rescue.yaml, 3 to 7 s): turning at about 0.5 rad/s moves the
// image by 7 px per frame, so the raw parallax makes a keyframe of almost every frame there and the window
// then spans a few tenths of a second; with the rotation compensated only the translation counts.
TEST(RunEstimatorTest, RotationCompensatedParallaxMakesFewerKeyframesInTurns) {
  sim::SimOptions sim_options;
  sim_options.duration_s = 7.0;
  sim_options.trajectory.type = sim::TrajectoryType::kRescue;
  sim_options.landmarks.layout = sim::LandmarkLayout::kRandom;
  sim_options.landmarks.random_count = 300;
  sim_options.landmarks.random_margin_m = 4.0;
  const Dataset data = sim::Simulate(sim_options, 3);
  const EstimatorInput input = testing::InputFromSimulation(sim_options, data, 3);
  EstimatorOptions raw;
  raw.max_frame_rate_hz = 0.0;  // every frame: 7 px of a turn's image motion between frames
  EstimatorOptions compensated = raw;
  compensated.window.parallax_compensates_rotation = true;
  const EstimatorResult a = RunEstimator(raw, input);
  const EstimatorResult b = RunEstimator(compensated, input);
  ASSERT_TRUE(a.ok) << a.failure_reason;
  ASSERT_TRUE(b.ok) << b.failure_reason;
  std::printf("keyframes over 7 s: raw parallax %d, rotation compensated %d\n", a.keyframes, b.keyframes);
  EXPECT_LT(b.keyframes, a.keyframes / 2);
  EXPECT_GT(b.keyframes, 5);
}

}  // namespace
}  // namespace vigil::estimator
