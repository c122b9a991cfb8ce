// Which frames the estimator solves under max_frame_rate_hz, and the poses it gives the frames between.
#include "estimator/solved_frames.h"

#include <set>

#include <gtest/gtest.h>

#include "core/interpolation.h"
#include "estimator/estimator.h"
#include "estimator/run_estimator.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// The frames the cap's pace takes from a camera at camera_hz (the first one at 0, the others jittered).
std::vector<int> Solved(double camera_hz, int count, double max_rate_hz, int64_t jitter_ns = 0) {
  std::vector<int> solved;
  FramePace pace(max_rate_hz);
  for (int k = 0; k < count; ++k) {
    const int64_t jitter = k == 0 ? 0 : (k % 2 == 0 ? jitter_ns : -jitter_ns);
    if (pace.Take(static_cast<int64_t>(k * 1e9 / camera_hz) + jitter)) solved.push_back(k);
  }
  return solved;
}

TEST(SolvedFrames, TheRateCapTakesEveryNthFrameOfARegularCamera) {
  EXPECT_EQ(Solved(30.0, 10, 10.0), (std::vector<int>{0, 3, 6, 9}));
  EXPECT_EQ(Solved(20.0, 7, 10.0), (std::vector<int>{0, 2, 4, 6}));
  // 2 ms of jitter either way does not make a 30 Hz camera skip a frame the 10 Hz cap allows.
  EXPECT_EQ(Solved(30.0, 10, 10.0, 2'000'000), (std::vector<int>{0, 3, 6, 9}));
  // A 25 Hz camera at 10 Hz: every third frame (8.3 Hz), never two 40 ms apart.
  EXPECT_EQ(Solved(25.0, 8, 10.0), (std::vector<int>{0, 3, 6}));
  // A cap above the camera's rate, and no cap, take every frame.
  EXPECT_EQ(Solved(20.0, 4, 30.0), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(Solved(30.0, 4, 0.0), (std::vector<int>{0, 1, 2, 3}));
}

struct CappedRun {
  sim::SimOptions sim_options;
  Dataset data;
  EstimatorInput input;
  CappedRun() {
    sim_options.duration_s = 6.0;
    data = sim::Simulate(sim_options, 3);
    input = testing::InputFromSimulation(sim_options, data, 3);
  }
  EstimatorResult Run(bool predict_between_solves) const {
    EstimatorOptions options;
    options.max_frame_rate_hz = 10.0;
    options.predict_between_solves = predict_between_solves;
    return RunEstimator(options, input);
  }
};

// A detector's flags on the IMU from 3.0 to 3.2 s: with solve_flagged_frames (the default) the capped run
// solves every camera frame from the first one after a flagged sample to the first one after the last;
// without it, every third frame throughout. Either way the trajectory has every third frame: the cap's pace
// does not shift after the frames solved for the flags, so a run's pose rate does not depend on its flags.
TEST(SolvedFrames, FramesAfterFlaggedSamplesAreSolved) {
  CappedRun run;
  const int64_t flag_from_ns = 3'000'000'000, flag_to_ns = 3'200'000'000;
  run.input.imu_flagged.assign(run.input.imu.size(), 0);
  for (std::size_t k = 0; k < run.input.imu.size(); ++k)
    run.input.imu_flagged[k] = run.input.imu[k].t_ns >= flag_from_ns && run.input.imu[k].t_ns <= flag_to_ns;
  EstimatorOptions options;
  options.max_frame_rate_hz = 10.0;
  std::set<int64_t> solved_with, solved_without;  // the tracked frames each run solved
  const EstimatorResult with_rule = RunEstimator(options, run.input, [&](Estimator& estimator) {
    solved_with.insert(estimator.newest_state().t_ns);
    return true;
  });
  options.solve_flagged_frames = false;
  const EstimatorResult without_rule = RunEstimator(options, run.input, [&](Estimator& estimator) {
    solved_without.insert(estimator.newest_state().t_ns);
    return true;
  });
  ASSERT_TRUE(with_rule.ok) << with_rule.failure_reason;
  ASSERT_TRUE(without_rule.ok) << without_rule.failure_reason;
  ASSERT_FALSE(solved_with.empty());
  ASSERT_LT(*solved_with.begin(), flag_from_ns);  // tracking before the flags
  const std::vector<CameraFrame>& frames = run.input.frames;
  int inside = 0;
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const int64_t t_ns = frames[k].t_ns;
    if (t_ns <= *solved_with.begin()) continue;
    // Frame k's interval (frames[k - 1], t] holds a flagged sample: the rule solves it.
    const bool after_flagged = frames[k - 1].t_ns < flag_to_ns && t_ns >= flag_from_ns;
    if (after_flagged) {
      ++inside;
      EXPECT_TRUE(solved_with.count(t_ns)) << "frame " << k;
    } else {
      EXPECT_EQ(solved_with.count(t_ns), solved_without.count(t_ns)) << "frame " << k;
    }
  }
  EXPECT_GE(inside, 6);  // 0.2 s of a 30 Hz camera
  EXPECT_GT(with_rule.solved_frames, without_rule.solved_frames + 3);
  // The trajectories have the same frames, the paced ones.
  ASSERT_EQ(with_rule.trajectory.size(), without_rule.trajectory.size());
  for (std::size_t i = 0; i < with_rule.trajectory.size(); ++i) {
    EXPECT_EQ(with_rule.trajectory[i].t_ns, without_rule.trajectory[i].t_ns) << "row " << i;
  }
  EXPECT_EQ(with_rule.trajectory.size(), solved_without.size());
}

// A short paper run at a cap of 10 of the camera's 30 frames per second, predicting between
// solves: every frame from the first tracked one on has a pose, the solved ones a covariance, and each
// predicted pose is within a centimetre of the error of the solved pose it was predicted from, so the
// prediction carries the state with the right time, gravity and biases.
TEST(SolvedFrames, FramesBetweenSolvedOnesGetTheImusPrediction) {
  const CappedRun run;
  const EstimatorInput& input = run.input;
  const Dataset& data = run.data;
  const EstimatorResult result = run.Run(true);
  ASSERT_TRUE(result.ok) << result.failure_reason;
  EXPECT_EQ(result.frames, static_cast<int>(input.frames.size()));
  ASSERT_FALSE(result.trajectory.empty());
  // Every third frame solved from the first on (the initialization's too); from the first tracked frame, a
  // solved one, one row per camera frame.
  std::set<int64_t> solved_ns;
  for (std::size_t k = 0; k < input.frames.size(); k += 3) solved_ns.insert(input.frames[k].t_ns);
  EXPECT_EQ(result.solved_frames, static_cast<int>(solved_ns.size()));
  std::size_t first = 0;
  while (input.frames[first].t_ns < result.trajectory.front().t_ns) ++first;
  EXPECT_EQ(first % 3, 0u);
  ASSERT_EQ(result.trajectory.size(), input.frames.size() - first);
  ASSERT_EQ(result.pose_covariances.size(), result.trajectory.size());
  int predicted = 0;
  Eigen::Vector3d solved_error = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < result.trajectory.size(); ++i) {
    const StampedPose& pose = result.trajectory[i];
    EXPECT_EQ(pose.t_ns, input.frames[first + i].t_ns);
    NavState truth;
    ASSERT_TRUE(InterpolateNavState(data.groundtruth, pose.t_ns, &truth));
    const Eigen::Vector3d error = pose.p_W - truth.p_W;
    if (solved_ns.count(pose.t_ns)) {
      EXPECT_TRUE(result.pose_covariances[i].allFinite()) << "solved row " << i;
      solved_error = error;
    } else {
      ++predicted;
      EXPECT_TRUE(result.pose_covariances[i].array().isNaN().all()) << "predicted row " << i;
      EXPECT_LT((error - solved_error).norm(), 0.01) << "predicted row " << i;
    }
  }
  EXPECT_GT(predicted, static_cast<int>(result.trajectory.size()) / 2);
}

// Without the predictions (the default) the trajectory is the solved frames' rows of the predicting run, bit
// for bit: predicting reads the estimator's state and changes nothing in it.
TEST(SolvedFrames, WithoutPredictionsTheTrajectoryHasTheSolvedFrames) {
  const CappedRun run;
  const EstimatorResult solved = run.Run(false);
  const EstimatorResult predicted = run.Run(true);
  ASSERT_TRUE(solved.ok) << solved.failure_reason;
  EXPECT_EQ(solved.solved_frames, predicted.solved_frames);
  EXPECT_EQ(solved.frames, predicted.frames);
  ASSERT_EQ(solved.pose_covariances.size(), solved.trajectory.size());
  std::size_t i = 0;
  for (std::size_t k = 0; k < predicted.trajectory.size(); ++k) {
    if (predicted.pose_covariances[k].array().isNaN().all()) continue;
    ASSERT_LT(i, solved.trajectory.size());
    EXPECT_EQ(solved.trajectory[i].t_ns, predicted.trajectory[k].t_ns);
    EXPECT_EQ(solved.trajectory[i].p_W, predicted.trajectory[k].p_W) << "row " << i;
    EXPECT_EQ(solved.pose_covariances[i], predicted.pose_covariances[k]) << "row " << i;
    ++i;
  }
  EXPECT_EQ(i, solved.trajectory.size());
  EXPECT_GT(predicted.trajectory.size(), 2 * solved.trajectory.size());  // every third frame solved
}

}  // namespace
}  // namespace vigil::estimator
