// The covariance after a keyframe from the oldest frame's terms as its marginalization linearized them
// (Estimator::LinearizedOldest) against the covariance that linearizes every term itself.
#include <gtest/gtest.h>

#include "bench/estimator_stages.h"
#include "estimator/run_estimator.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// Every full window of a short simulated run (after its slide: one frame short of the capacity), as if the
// oldest frame left next: the same covariance to rounding (the gauge makes it ill-conditioned: 1e-9 of
// its norm apart).
TEST(LinearizedOldest, TheCovarianceIsTheOneThatLinearizesEveryTerm) {
  const auto [data, input] = testing::SimulatePaperRun(5.0, 3);
  EstimatorOptions options;
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
  ASSERT_TRUE(result.ok) << result.failure_reason;
  EXPECT_GT(compared, 20) << compared;
}

}  // namespace
}  // namespace vigil::estimator
