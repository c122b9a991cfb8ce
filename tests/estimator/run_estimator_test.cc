#include "estimator/run_estimator.h"

#include <utility>

#include <gtest/gtest.h>

#include "core/error.h"

#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

TEST(RunEstimatorTest, ShortPaperRunIsAccurate) {
  sim::SimOptions sim_options;
  sim_options.duration_s = 5.0;
  const Dataset data = sim::Simulate(sim_options, 1);
  const EstimatorInput input = testing::InputFromSimulation(sim_options, data, 1);
  const EstimatorResult result = RunEstimator(EstimatorOptions{}, input);
  ASSERT_TRUE(result.ok) << result.failure_reason;
  // One state per frame once the first full window (size + 1 frames) is initialized.
  EXPECT_EQ(result.states.size(), data.frames.size() - EstimatorOptions{}.window.size);
  const double ate = testing::PosYawAteRmse(result.states, data.groundtruth);
  std::printf("ATE %.4f m, frames %d keyframes %d, optimize %.3f s marginalize %.3f s\n", ate, result.frames,
              result.keyframes, result.timing.optimize_s, result.timing.marginalize_s);
  EXPECT_LT(ate, 0.1);
}

TEST(RunEstimatorTest, SameInputGivesTheSameOutputBitForBit) {
  sim::SimOptions sim_options;
  sim_options.duration_s = 1.0;
  const Dataset data = sim::Simulate(sim_options, 2);
  const EstimatorInput input = testing::InputFromSimulation(sim_options, data, 2);
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
  sim::SimOptions sim_options;
  sim_options.duration_s = 3.0;
  const Dataset data = sim::Simulate(sim_options, 3);
  EstimatorInput input = testing::InputFromSimulation(sim_options, data, 3);
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
  sim::SimOptions sim_options;
  sim_options.duration_s = 1.0;
  const Dataset data = sim::Simulate(sim_options, 4);
  EstimatorInput input = testing::InputFromSimulation(sim_options, data, 4);
  EstimatorInput no_truth = input;
  no_truth.groundtruth.clear();
  EXPECT_THROW(RunEstimator(EstimatorOptions{}, no_truth), InputError);
  EstimatorInput unordered = input;
  std::swap(unordered.frames[3], unordered.frames[4]);
  EXPECT_THROW(RunEstimator(EstimatorOptions{}, unordered), InputError);
}

}  // namespace
}  // namespace vigil::estimator
