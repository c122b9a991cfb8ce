#include "experiments/runs/run_metrics.h"

#include <gtest/gtest.h>

namespace vigil::experiments {
namespace {

TEST(RunMetrics, HasEveryKeyOfFormatsMdAndReportsFailure) {
  RunSummary summary;
  summary.seed = 3;
  summary.duration_s = 20.0;
  summary.wall.total_s = 1.5;
  estimator::EstimatorResult result;
  result.ok = false;
  result.failure_reason = "diverged: |b_a| > 2.5";
  result.frames = 100;
  result.timing.optimize_s = 0.2;
  const nlohmann::json detection = {{"detector", "none"}, {"flagged_samples", 0}};
  const nlohmann::json m = RunMetricsJson(summary, result, evaluation::TrajectoryEvaluation{}, detection);
  EXPECT_EQ(m["status"], "failed");
  EXPECT_EQ(m["failure_reason"], "diverged: |b_a| > 2.5");
  EXPECT_EQ(m["seed"], 3);
  EXPECT_EQ(m["duration_s"], 20.0);
  for (const char* key : {"simulate", "detect", "estimate", "evaluate", "total"})
    EXPECT_TRUE(m["wall_time_s"].contains(key)) << key;
  for (const char* key : {"init", "initialized_at_s", "resets", "frames", "keyframes"})
    EXPECT_TRUE(m["estimator"].contains(key)) << key;
  EXPECT_TRUE(m["estimator"]["initialized_at_s"].is_null());  // never initialized
  EXPECT_DOUBLE_EQ(m["estimator"]["timing"]["optimize_ms_per_frame"], 2.0);
  EXPECT_TRUE(m.contains("ate") && m.contains("relative") && m.contains("coverage"));
  EXPECT_EQ(m["detection"]["detector"], "none");
  const std::string line = RunSummaryLine(m);
  EXPECT_NE(line.find("failed (diverged: |b_a| > 2.5)"), std::string::npos) << line;
  EXPECT_NE(line.find("wall 1.50 s"), std::string::npos) << line;
  EXPECT_NE(line.find(": no ATE (coverage 0.0 %)"), std::string::npos) << line;  // nothing to align
  EXPECT_EQ(line.find("nan"), std::string::npos) << line;
  EXPECT_EQ(m["estimator"]["marginalization_failures"], 0);
  EXPECT_EQ(line.find("marginalization"), std::string::npos) << line;  // said only when one failed

  // A failed marginalization (the prior was dropped) is counted and said.
  result.marginalization_failures = 2;
  const nlohmann::json dropped =
      RunMetricsJson(summary, result, evaluation::TrajectoryEvaluation{}, detection);
  EXPECT_EQ(dropped["estimator"]["marginalization_failures"], 2);
  EXPECT_NE(RunSummaryLine(dropped).find(", 2 failed marginalizations (prior dropped), detector none"),
            std::string::npos)
      << RunSummaryLine(dropped);

  // The IMU noise measured at rest: nothing measured is null, a measured density is written with its use.
  EXPECT_EQ(m["estimator"]["imu_noise_at_rest"]["rest_s"], 0.0);
  EXPECT_TRUE(m["estimator"]["imu_noise_at_rest"]["accel_noise_density"].is_null());
  result.rest_noise.rest_s = 4.25;
  result.rest_noise.accel_noise_density = 0.0197;
  result.rest_noise.accel_applied = true;
  result.rest_noise.gyro_bias_walk_applied = true;
  const nlohmann::json rest = RunMetricsJson(summary, result, evaluation::TrajectoryEvaluation{}, detection);
  EXPECT_EQ(rest["estimator"]["imu_noise_at_rest"]["rest_s"], 4.25);
  EXPECT_EQ(rest["estimator"]["imu_noise_at_rest"]["accel_noise_density"], 0.0197);
  EXPECT_EQ(rest["estimator"]["imu_noise_at_rest"]["accel_applied"], true);
  EXPECT_EQ(rest["estimator"]["imu_noise_at_rest"]["gyro_bias_walk_applied"], true);
  EXPECT_EQ(rest["estimator"]["imu_noise_at_rest"]["accel_bias_walk_applied"], false);
  EXPECT_TRUE(rest["estimator"]["imu_noise_at_rest"]["gyro_noise_density"].is_null());
}

// A run whose errors rest on too little of it is neither ok nor diverged, and the summary line says why; an
// undefined alignment gives no ATE rather than an arbitrary yaw's.
TEST(RunMetrics, InconclusiveRunsHaveTheirOwnVerdict) {
  RunSummary summary;
  estimator::EstimatorResult result;
  evaluation::TrajectoryEvaluation ev;
  ev.matched_poses = 2;
  ev.gt_poses = 91;
  ev.coverage = 2.0 / 91.0;
  ev.ate_trans_m = evaluation::ComputeStatistics({0.0004, 0.0004});
  ev.ate_rot_deg = evaluation::ComputeStatistics({0.1, 0.1});
  ev.inconclusive_reason =
      "coverage 2.2 % (2 of 91 ground-truth poses) is below evaluation.min_coverage 25.0 %";
  const nlohmann::json detection = {{"detector", "none"}};
  const nlohmann::json few = RunMetricsJson(summary, result, ev, detection);
  EXPECT_EQ(few["status"], kInconclusive);
  EXPECT_EQ(few["failure_reason"], ev.inconclusive_reason);
  EXPECT_NE(RunSummaryLine(few).find("inconclusive (coverage 2.2 %"), std::string::npos)
      << RunSummaryLine(few);

  ev.coverage = 1.0;
  ev.alignment_defined = false;
  ev.alignment_extent_m = 0.011;
  ev.ate_trans_m = ev.ate_rot_deg = evaluation::ErrorStatistics{};
  ev.inconclusive_reason = "the matched ground truth spans 0.011 m";
  const nlohmann::json still = RunMetricsJson(summary, result, ev, detection);
  EXPECT_EQ(still["status"], kInconclusive);
  EXPECT_EQ(still["ate"]["alignment_defined"], false);
  const std::string line = RunSummaryLine(still);
  EXPECT_NE(line.find(": no ATE (posyaw alignment undefined over 0.011 m, coverage 100.0 %)"),
            std::string::npos)
      << line;

  // A relative-error distance with no segment along 0.011 m is said so, not printed as "nan m".
  ev.relative.emplace_back().distance_m = 7.0;
  const std::string no_segment = RunSummaryLine(RunMetricsJson(summary, result, ev, detection));
  EXPECT_NE(no_segment.find(", RE 7 m: no segment,"), std::string::npos) << no_segment;
  EXPECT_EQ(no_segment.find("nan"), std::string::npos) << no_segment;
}

}  // namespace
}  // namespace vigil::experiments
