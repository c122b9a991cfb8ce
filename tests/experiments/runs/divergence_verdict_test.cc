// The `diverged` verdict (evaluation.divergence): runs built with a known error against a known distance
// travelled, through the evaluation, metrics.json, the summary line and the sweep aggregate.
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "evaluation/evaluate_trajectory.h"
#include "experiments/runs/run_metrics.h"
#include "experiments/sweeps/sweep_aggregate.h"

namespace vigil::experiments {
namespace {

constexpr int64_t kVerdictFrameNs = 50'000'000;  // 20 Hz

// 70 s along a straight line at 1 m/s (70 m travelled).
Trajectory SeventyMetreLine() {
  Trajectory gt;
  for (int k = 0; k <= 1400; ++k) {
    const double t_s = 0.05 * k;
    gt.push_back({k * kVerdictFrameNs, Eigen::Vector3d(t_s, 0.0, 1.0), Eigen::Quaterniond::Identity()});
  }
  return gt;
}

// The ground truth with a vertical drift growing linearly to `final_drift_m` (no posyaw alignment removes a
// vertical drift) plus a +-1 cm wiggle.
Trajectory DriftedUpward(const Trajectory& gt, double final_drift_m) {
  Trajectory est = gt;
  for (std::size_t k = 0; k < est.size(); ++k) {
    const double fraction = static_cast<double>(k) / static_cast<double>(est.size() - 1);
    est[k].p_W.z() += final_drift_m * fraction + 0.01 * std::sin(0.7 * static_cast<double>(k));
  }
  return est;
}

nlohmann::json VerdictMetrics(const evaluation::TrajectoryEvaluation& evaluation) {
  RunSummary summary;
  estimator::EstimatorResult result;  // the estimator finished without a failure
  return RunMetricsJson(summary, result, evaluation, {{"detector", "none"}});
}

TEST(DivergenceVerdict, AKilometreOfDriftIn70SecondsIsDiverged) {
  const Trajectory gt = SeventyMetreLine();
  const evaluation::TrajectoryEvaluation ev =
      evaluation::EvaluateTrajectory(gt, DriftedUpward(gt, 1000.0), evaluation::EvaluationOptions{});
  EXPECT_NEAR(ev.gt_length_m, 70.0, 1e-6);
  // Bound: 0.4 % of 70 m + 0.5 m.
  EXPECT_NEAR(ev.divergence_bound_m, 0.78, 1e-9);
  EXPECT_TRUE(ev.diverged);
  const nlohmann::json m = VerdictMetrics(ev);
  EXPECT_EQ(m["status"], "diverged");
  EXPECT_EQ(m["divergence"]["diverged"], true);
  const std::string line = RunSummaryLine(m);
  EXPECT_EQ(line.rfind("diverged (ATE RMSE ", 0), 0u) << line;
  EXPECT_NE(line.find("exceeds 0.780 m"), std::string::npos) << line;
}

TEST(DivergenceVerdict, AGoodRunIsOk) {
  const Trajectory gt = SeventyMetreLine();
  const evaluation::TrajectoryEvaluation ev =
      evaluation::EvaluateTrajectory(gt, DriftedUpward(gt, 0.1), evaluation::EvaluationOptions{});
  EXPECT_FALSE(ev.diverged);
  const nlohmann::json m = VerdictMetrics(ev);
  EXPECT_EQ(m["status"], "ok");
  EXPECT_EQ(m["failure_reason"], "");
}

// The bound sits where the options put it: an error just above it is diverged, just below it is ok.
TEST(DivergenceVerdict, TheBoundFollowsTheOptions) {
  const Trajectory gt = SeventyMetreLine();
  evaluation::EvaluationOptions options;
  options.divergence.length_fraction = 0.01;  // 0.7 m over 70 m
  options.divergence.margin_m = 0.3;          // bound 1.0 m
  // A linear drift to D has an RMSE of about D / sqrt(12) once the alignment removes its mean offset.
  EXPECT_FALSE(evaluation::EvaluateTrajectory(gt, DriftedUpward(gt, 3.2), options).diverged);
  EXPECT_TRUE(evaluation::EvaluateTrajectory(gt, DriftedUpward(gt, 3.8), options).diverged);
}

// A failed estimator stays failed whatever its error; a diverged run is counted as diverged and its error
// still enters the cell's mean (the tables' means are those of every finished run).
TEST(DivergenceVerdict, SweepCellsCountDivergedRunsAndKeepTheirErrors) {
  const Trajectory gt = SeventyMetreLine();
  const evaluation::TrajectoryEvaluation bad =
      evaluation::EvaluateTrajectory(gt, DriftedUpward(gt, 1000.0), evaluation::EvaluationOptions{});
  const evaluation::TrajectoryEvaluation good =
      evaluation::EvaluateTrajectory(gt, DriftedUpward(gt, 0.1), evaluation::EvaluationOptions{});
  estimator::EstimatorResult failed;
  failed.ok = false;
  failed.failure_reason = "gyro bias norm 1.2 rad/s";
  const nlohmann::json failed_metrics = RunMetricsJson(RunSummary{}, failed, bad, {{"detector", "none"}});
  EXPECT_EQ(failed_metrics["status"], "failed");

  CellResult cell;
  AddRunMetrics(VerdictMetrics(bad), {}, &cell);
  AddRunMetrics(VerdictMetrics(good), {}, &cell);
  AddRunMetrics(failed_metrics, {}, &cell);
  EXPECT_EQ(cell.runs, 3u);
  EXPECT_EQ(cell.diverged, 1u);
  EXPECT_EQ(cell.failed, 1u);
  EXPECT_EQ(cell.ok(), 1u);
  ASSERT_EQ(cell.ate_rmse_m.size(), 2u);
  EXPECT_GT(cell.ate_rmse_m[0], 250.0);  // 1000 m / sqrt(12)
}

// A run that covers almost nothing (two matched poses of 1401) is inconclusive: whatever its ATE, it is
// left out of the cell's mean and counted with the failed runs, and apart as inconclusive.
TEST(DivergenceVerdict, SweepCellsKeepInconclusiveRunsOutOfTheMeans) {
  const Trajectory gt = SeventyMetreLine();
  const Trajectory two_poses(gt.begin(), gt.begin() + 2);
  const evaluation::TrajectoryEvaluation tiny =
      evaluation::EvaluateTrajectory(gt, two_poses, evaluation::EvaluationOptions{});
  const nlohmann::json tiny_metrics = VerdictMetrics(tiny);
  EXPECT_EQ(tiny_metrics["status"], "inconclusive");
  const evaluation::TrajectoryEvaluation good =
      evaluation::EvaluateTrajectory(gt, DriftedUpward(gt, 0.1), evaluation::EvaluationOptions{});

  CellResult cell;
  AddRunMetrics(tiny_metrics, {}, &cell);
  AddRunMetrics(VerdictMetrics(good), {}, &cell);
  EXPECT_EQ(cell.runs, 2u);
  EXPECT_EQ(cell.failed, 1u);
  EXPECT_EQ(cell.inconclusive, 1u);
  EXPECT_EQ(cell.ok(), 1u);
  ASSERT_EQ(cell.ate_rmse_m.size(), 1u);
  EXPECT_NEAR(cell.ate_rmse_m[0], good.ate_trans_m.rmse, 1e-12);
  EXPECT_EQ(cell.failure_reasons.begin()->first, tiny.inconclusive_reason);
  CellResult pooled;
  pooled.Merge(cell);
  EXPECT_EQ(pooled.inconclusive, 1u);
}

}  // namespace
}  // namespace vigil::experiments
