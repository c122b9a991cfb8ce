// window.oldest_tracks points: the long tracks kept as landmark points in W (estimator_points.cc). The points
// live while their tracks do, the priors hold only live blocks, and the dense solve of a window with points
// is the Ceres solve of it.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include <gtest/gtest.h>

#include "bench/estimator_stages.h"
#include "estimator/run_estimator.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// Points from the first frame that leaves the window after initialization on (point_settle_s 0), at most
// `max_points` of them (0: no cap).
EstimatorOptions WithPoints(double settle_s = 0.0, int max_points = 0) {
  EstimatorOptions options;
  options.window.oldest_tracks = OldestTracks::kPoints;
  options.window.point_settle_s = settle_s;
  options.window.point_max = max_points;
  return options;
}

// No track anchored in a frame earlier than point_settle_s after the initialization becomes a point.
TEST(LandmarkPoints, NoneBeforeTheEstimatorSettled) {
  const auto [data, input] = testing::SimulatePaperRun(12.0, 2);
  for (const double settle_s : {0.0, 3.0}) {
    SCOPED_TRACE(settle_s);
    double first_point_s = -1.0;
    std::optional<int64_t> initialized_ns;
    const EstimatorResult result = RunEstimator(WithPoints(settle_s), input, [&](Estimator& estimator) {
      const EstimatorStages stages(&estimator);
      if (estimator.initialized() && !initialized_ns) initialized_ns = estimator.newest_state().t_ns;
      if (first_point_s < 0.0 && stages.points() > 0)
        first_point_s = NsToS(stages.oldest_frame_ns() - *initialized_ns);
      return true;
    });
    ASSERT_TRUE(result.ok) << result.failure_reason;
    ASSERT_GE(first_point_s, 0.0);
    EXPECT_GE(first_point_s, settle_s);
    EXPECT_LT(first_point_s, settle_s + 1.5);  // the first keyframe slide after it, with a qualifying track
  }
}

// At most point_max of them live at once, each while its track does; the priors hold only live blocks.
TEST(LandmarkPoints, LiveWhileTheirTracksAreAndThePriorsHoldOnlyLiveBlocks) {
  const auto [data, input] = testing::SimulatePaperRun(8.0, 2);
  int frames_with_points = 0, most_points = 0;
  const EstimatorResult result = RunEstimator(WithPoints(0.0, 12), input, [&](Estimator& estimator) {
    const EstimatorStages stages(&estimator);
    EXPECT_TRUE(stages.PointsAndPriorsAreLive());
    frames_with_points += stages.points() > 0;
    most_points = std::max(most_points, stages.points());
    return true;
  });
  ASSERT_TRUE(result.ok) << result.failure_reason;
  EXPECT_GT(frames_with_points, 15);
  EXPECT_EQ(most_points, 12);  // window.point_max
  // Every solved pose has a covariance at the default rate, the points' information included.
  int covariances = 0;
  for (const Matrix6d& P : result.pose_covariances) covariances += P.allFinite();
  EXPECT_GT(covariances, 40);
}

// From the same states (a step away from the estimate, so that the solves move), the two solvers reach the
// same frames and points: the dense solve's points are blocks of its window like the frames.
TEST(LandmarkPoints, TheDenseSolveIsTheCeresSolve) {
  const auto [data, input] = testing::SimulatePaperRun(8.0, 2);
  const Eigen::Vector3d newest_offset_m(0.03, -0.02, 0.01), points_offset_m(-0.01, 0.0, 0.02);
  int compared = 0;
  const EstimatorResult result = RunEstimator(WithPoints(), input, [&](Estimator& estimator) {
    EstimatorStages stages(&estimator);
    if (stages.points() < 5 || compared >= 10) return true;
    stages.OffsetSaved(newest_offset_m, points_offset_m);
    EXPECT_TRUE(stages.Solve(SolverBackend::kDense));
    const std::array<double, kPoseSize> dense = stages.NewestPose();
    const std::map<int, std::array<double, kPointSize>> dense_points = stages.points_W();
    EXPECT_TRUE(stages.Solve(SolverBackend::kCeres));
    const std::array<double, kPoseSize> ceres = stages.NewestPose();
    double points_moved = 0.0, points_apart = 0.0, newest_apart = 0.0;
    for (const auto& [id, p_W] : stages.points_W())
      for (int i = 0; i < 3; ++i) {
        points_moved = std::max(points_moved, std::abs(p_W[i] - stages.saved_points_W().at(id)[i]));
        points_apart = std::max(points_apart, std::abs(p_W[i] - dense_points.at(id)[i]));
      }
    for (int i = 0; i < kPoseSize; ++i) newest_apart = std::max(newest_apart, std::abs(dense[i] - ceres[i]));
    EXPECT_GT(points_moved, 1e-3);
    EXPECT_LT(points_apart, 1e-8);
    EXPECT_LT(newest_apart, 1e-8);
    stages.OffsetSaved(-newest_offset_m, -points_offset_m);
    stages.Restore();
    ++compared;
    return true;
  });
  ASSERT_TRUE(result.ok) << result.failure_reason;
  EXPECT_EQ(compared, 10);
}

}  // namespace
}  // namespace vigil::estimator
