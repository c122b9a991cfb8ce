// What the tracks anchored in the oldest frame become when it leaves the window (OldestTracks): VINS-Mono's
// re-anchoring uses observations the prior already holds once more, so the window claims more information
// than restarting the tracks, which uses each observation once.
#include <cstdio>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "estimator/pose_covariance.h"
#include "estimator/run_estimator.h"
#include "evaluation/statistics.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// The median over a run of the newest position's variance (trace of the covariance's position block), over
// the poses that have a covariance (EstimatorOptions::covariance_rate_hz).
double MedianPositionVariance(OldestTracks policy, const EstimatorInput& input) {
  EstimatorOptions options;
  options.window.oldest_tracks = policy;
  const EstimatorResult result = RunEstimator(options, input);
  EXPECT_TRUE(result.ok) << result.failure_reason;
  std::vector<double> variance;
  for (const Matrix6d& P : result.pose_covariances)
    if (P.allFinite()) variance.push_back(P.topLeftCorner<3, 3>().trace());
  EXPECT_FALSE(variance.empty());
  return evaluation::ComputeStatistics(std::move(variance)).median;
}

TEST(OldestTracks, ReanchoringClaimsMoreInformationThanRestarting) {
  const auto [data, input] = testing::SimulatePaperRun(8.0, 4);
  const double reanchor = MedianPositionVariance(OldestTracks::kReanchor, input);
  const double restart = MedianPositionVariance(OldestTracks::kRestart, input);
  std::printf("median position variance: reanchor %.3g m^2, restart %.3g m^2\n", reanchor, restart);
  EXPECT_GT(restart, 1.5 * reanchor);
}

}  // namespace
}  // namespace vigil::estimator
