// The covariance after a keyframe from the oldest frame's terms as its marginalization linearized them
// (Estimator::LinearizedOldest) against the covariance that linearizes every term itself.
#include <filesystem>

#include <gtest/gtest.h>

#include "bench/estimator_stages.h"
#include "estimator/run_estimator.h"
#include "experiments/runs/run_config.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// Every full window of the run (after its slide: one frame short of the capacity), as if the oldest frame
// left next: the same covariance to rounding (the gauge makes it ill-conditioned: 1e-9 of its norm apart).
// Returns how many windows were compared.
int CompareOnEveryFullWindow(const EstimatorOptions& options, const EstimatorInput& input) {
  int compared = 0;
  const EstimatorResult result = RunEstimator(options, input, [&](Estimator& estimator) {
    EstimatorStages stages(&estimator);
    if (!estimator.initialized() || stages.window_frames() + 1 < estimator.window_frames()) return true;
    const std::optional<Matrix6d> shared = stages.CovarianceAndMarginalize(true);
    const std::optional<Matrix6d> unshared = stages.CovarianceAndMarginalize(false);
    EXPECT_TRUE(shared && unshared);
    if (shared && unshared) {
      EXPECT_LT((*shared - *unshared).norm(), 1e-7 * unshared->norm());
      ++compared;
    }
    return true;
  });
  EXPECT_TRUE(result.ok) << result.failure_reason;
  return compared;
}

// A moving platform: the oldest frame's IMU factor, its tracks, and at first its bias prior.
TEST(LinearizedOldest, TheCovarianceIsTheOneThatLinearizesEveryTerm) {
  const auto [data, input] = testing::SimulatePaperRun(5.0, 3);
  EXPECT_GT(CompareOnEveryFullWindow(EstimatorOptions{}, input), 20);
}

// The IMU simulated along EuRoC V1_01, which stands still until 5.3 s: the static start holds the window with
// zero-velocity terms, those over the oldest frame among them.
TEST(LinearizedOldest, TheCovarianceOfAWindowAtRestToo) {
  experiments::RunConfig config = experiments::LoadRunConfig(
      (std::filesystem::path(VIGIL_SOURCE_DIR) / "configs/recording_v1_01.yaml").string());
  config.sim.duration_s = 7.0;
  config.estimator.init = InitMode::kVins;
  ASSERT_TRUE(config.estimator.zero_velocity.static_init);
  const Dataset data = sim::Simulate(config.sim, 1);
  EXPECT_GT(
      CompareOnEveryFullWindow(config.estimator, experiments::MakeEstimatorInput(config, data, data.imu)),
      30);
}

}  // namespace
}  // namespace vigil::estimator
