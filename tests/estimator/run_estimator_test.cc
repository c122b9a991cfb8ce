#include "estimator/run_estimator.h"

#include <gtest/gtest.h>

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
  EXPECT_GT(result.states.size(), data.frames.size() - 2);
  const double ate = testing::PosYawAteRmse(result.states, data.groundtruth);
  std::printf("ATE %.4f m, frames %d keyframes %d, optimize %.3f s marginalize %.3f s\n", ate, result.frames,
              result.keyframes, result.timing.optimize_s, result.timing.marginalize_s);
  EXPECT_LT(ate, 0.1);
}

}  // namespace
}  // namespace vigil::estimator
