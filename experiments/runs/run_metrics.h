// metrics.json of a run (docs/formats.md): status, seed, duration, stage wall times, estimator summary and
// timing per frame, ATE, relative errors, coverage and detection statistics.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "estimator/estimator_input.h"
#include "estimator/estimator_options.h"
#include "evaluation/evaluate_trajectory.h"

namespace vigil::experiments {

// Wall-clock seconds of the stages of one run.
struct RunWallTimes {
  double simulate_s = 0.0;   // simulation, or reading the dataset
  double templates_s = 0.0;  // resolving the DTW template library (0 for other detectors)
  double detect_s = 0.0;
  double estimate_s = 0.0;
  double evaluate_s = 0.0;
  double total_s = 0.0;
};

struct RunSummary {
  uint64_t seed = 0;
  double duration_s = 0.0;  // recorded time span of the data
  estimator::InitMode init = estimator::InitMode::kGroundTruth;
  RunWallTimes wall;
};

// The verdict of a run whose errors rest on too little of it (evaluation.inconclusive_reason): like a
// failed run it is left out of every mean and counted with the failed runs of the tables.
inline constexpr const char* kInconclusive = "inconclusive";

// status "failed" with result.failure_reason when !result.ok, kInconclusive (with the evaluation's reason)
// when the coverage or the alignment's motion is too small, "failed" when the ATE is not finite, "diverged"
// (with the error and the bound as failure_reason) when evaluation.diverged, else "ok"; the evaluation
// describes what the estimator produced (possibly nothing); `detection` is the "detection" object
// (detection_stage.h).
nlohmann::json RunMetricsJson(const RunSummary& summary, const estimator::EstimatorResult& result,
                              const evaluation::TrajectoryEvaluation& evaluation,
                              const nlohmann::json& detection);

// A run of a recording without ground truth: the estimate is written, the metrics are not computed. Sets
// status from the estimator alone ("ok" or "failed" with its reason) and "evaluation": kEvaluationSkipped;
// the ATE and relative errors are then null and coverage 0.
inline constexpr const char* kEvaluationSkipped = "skipped: the dataset has no ground truth";
void SkipEvaluation(const estimator::EstimatorResult& result, nlohmann::json* metrics);

// A run of an external estimator (metrics["external"]): "estimator" says so ("backend": "external", "init":
// "external", the estimator's own start) and its counters of vigil's estimator (keyframes, resets, stops,
// failure checks, marginalization failures, timing, mitigation, IMU noise at rest) are null: that estimator
// did not run. A run of vigil's own estimator has "backend": "builtin".
void DescribeExternalEstimator(nlohmann::json* metrics);

// "vigil run: ok, ATE RMSE 0.043 m, ... wall 0.85 s": the one-line summary of a metrics.json document.
std::string RunSummaryLine(const nlohmann::json& metrics);

}  // namespace vigil::experiments
