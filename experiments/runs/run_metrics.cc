#include "experiments/runs/run_metrics.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/format.h"
#include "evaluation/metrics_access.h"

namespace vigil::experiments {
namespace {

double PerFrameMs(double seconds, int frames) { return frames > 0 ? 1e3 * seconds / frames : 0.0; }

}  // namespace

nlohmann::json RunMetricsJson(const RunSummary& summary, const estimator::EstimatorResult& result,
                              const evaluation::TrajectoryEvaluation& evaluation,
                              const nlohmann::json& detection) {
  nlohmann::json m;
  // An estimate whose errors cannot be computed (no matched pose, non-finite values) is no success; one
  // whose error leaves the divergence bound (evaluation_options.h) is diverged.
  const bool evaluated =
      std::isfinite(evaluation.ate_trans_m.rmse) && std::isfinite(evaluation.ate_rot_deg.rmse);
  if (!result.ok) {
    m["status"] = "failed";
    m["failure_reason"] = result.failure_reason;
  } else if (!evaluation.inconclusive_reason.empty()) {
    m["status"] = kInconclusive;
    m["failure_reason"] = evaluation.inconclusive_reason;
  } else if (!evaluated) {
    m["status"] = "failed";
    m["failure_reason"] = "evaluation: the ATE is not finite (" + std::to_string(evaluation.matched_poses) +
                          " matched poses); check the ground truth and the estimate";
  } else if (evaluation.diverged) {
    m["status"] = "diverged";
    m["failure_reason"] = "ATE RMSE " + FormatFixed(evaluation.ate_trans_m.rmse, 3) + " m exceeds " +
                          FormatFixed(evaluation.divergence_bound_m, 3) + " m (divergence bound over " +
                          FormatFixed(evaluation.gt_length_m, 1) + " m travelled)";
  } else {
    m["status"] = "ok";
    m["failure_reason"] = "";
  }
  m["seed"] = summary.seed;
  m["duration_s"] = summary.duration_s;
  const RunWallTimes& w = summary.wall;
  m["wall_time_s"] = {{"simulate", w.simulate_s}, {"templates", w.templates_s}, {"detect", w.detect_s},
                      {"estimate", w.estimate_s}, {"evaluate", w.evaluate_s},   {"total", w.total_s}};
  const estimator::EstimatorTiming& t = result.timing;
  m["estimator"] = {{"backend", "builtin"},
                    {"init", summary.init == estimator::InitMode::kVins ? "vins" : "groundtruth"},
                    {"initialized_at_s", evaluation::NumberOrNull(result.initialized_at_s)},
                    {"resets", result.resets},
                    {"stops", result.stops},
                    {"failure_checks", result.failure_checks},
                    {"frames", result.frames},
                    {"solved_frames", result.solved_frames},
                    {"keyframes", result.keyframes},
                    {"marginalization_failures", result.marginalization_failures},
                    {"output_poses", result.trajectory.size()},
                    {"timing",
                     {{"optimize_s", t.optimize_s},
                      {"marginalize_s", t.marginalize_s},
                      {"initialize_s", t.initialize_s},
                      {"covariance_s", t.covariance_s},
                      {"optimizations", t.optimizations},
                      {"marginalizations", t.marginalizations},
                      {"optimize_ms_per_frame", PerFrameMs(t.optimize_s, result.frames)},
                      {"marginalize_ms_per_frame", PerFrameMs(t.marginalize_s, result.frames)},
                      {"covariance_ms_per_frame", PerFrameMs(t.covariance_s, result.frames)},
                      {"estimate_ms_per_frame", PerFrameMs(w.estimate_s, result.frames)}}}};
  const estimator::MitigationStats& mit = result.mitigation;
  m["estimator"]["mitigation"] = {{"repeated_timestamps", mit.repeated_timestamps},
                                  {"inflated_samples", mit.inflated_samples},
                                  {"clipped_samples", mit.clipped_samples},
                                  {"gate_tests", mit.gate_tests},
                                  {"gated_factors", mit.gated_factors},
                                  {"gated_resolves", mit.gated_resolves}};
  const estimator::RestNoise& rest = result.rest_noise;
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  m["estimator"]["imu_noise_at_rest"] = {
      {"start_s", rest.start_s},
      {"rest_s", rest.rest_s},
      {"tau_s", rest.tau_s},
      {"differences", rest.differences},
      {"gyro_noise_density", evaluation::NumberOrNull(rest.gyro_noise_density.value_or(kNone))},
      {"accel_noise_density", evaluation::NumberOrNull(rest.accel_noise_density.value_or(kNone))},
      {"gyro_applied", rest.gyro_applied},
      {"accel_applied", rest.accel_applied},
      {"gyro_bias_walk_applied", rest.gyro_bias_walk_applied},
      {"accel_bias_walk_applied", rest.accel_bias_walk_applied}};
  m.update(evaluation::EvaluationJson(evaluation));  // "ate", "relative", "coverage", "gt_length_m"
  m["detection"] = detection;
  return m;
}

void DescribeExternalEstimator(nlohmann::json* metrics) {
  nlohmann::json& e = (*metrics)["estimator"];
  e["backend"] = "external";
  e["init"] = "external";
  for (const char* key : {"resets", "stops", "failure_checks", "solved_frames", "keyframes",
                          "marginalization_failures", "timing", "mitigation", "imu_noise_at_rest"})
    e[key] = nullptr;
}

void SkipEvaluation(const estimator::EstimatorResult& result, nlohmann::json* metrics) {
  nlohmann::json& m = *metrics;
  m["status"] = result.ok ? "ok" : "failed";
  m["failure_reason"] = result.ok ? "" : result.failure_reason;
  m["evaluation"] = kEvaluationSkipped;
}

std::string RunSummaryLine(const nlohmann::json& m) {
  std::string s = m.at("status").get<std::string>();
  const std::string reason = m.at("failure_reason").get<std::string>();
  if (!reason.empty()) s += " (" + reason + ")";
  char buf[256];
  if (m.value("evaluation", std::string()) == kEvaluationSkipped) {
    std::snprintf(buf, sizeof(buf), ": %s; %lld poses estimated", kEvaluationSkipped,
                  static_cast<long long>(m["estimator"].value("output_poses", 0)));
    return s + buf;
  }
  const nlohmann::json& ate = m.at("ate");
  // An alignment without the motion to define it has no ATE (evaluation_options.h); older files lack the key.
  const double ate_m = evaluation::MetricNumber(ate, {"trans_m", "rmse"});
  if (!ate.value("alignment_defined", true))
    std::snprintf(buf, sizeof(buf), ": no ATE (%s alignment undefined over %.3f m, coverage %.1f %%)",
                  ate.at("align").get<std::string>().c_str(),
                  evaluation::MetricNumber(ate, {"alignment_extent_m"}),
                  100.0 * evaluation::MetricNumber(m, {"coverage"}));
  else if (!std::isfinite(ate_m))  // nothing matched (a failed run's empty trajectory)
    std::snprintf(buf, sizeof(buf), ": no ATE (coverage %.1f %%)",
                  100.0 * evaluation::MetricNumber(m, {"coverage"}));
  else
    std::snprintf(buf, sizeof(buf), ": ATE RMSE %.4f m (%s, coverage %.1f %%)", ate_m,
                  ate.at("align").get<std::string>().c_str(),
                  100.0 * evaluation::MetricNumber(m, {"coverage"}));
  s += buf;
  if (!m.at("relative").empty()) {
    const nlohmann::json& r = m.at("relative").front();
    const double trans_m = evaluation::MetricNumber(r, {"trans_m", "mean"});
    // No segment of that length (a short or inconclusive run): said, not printed as "nan m".
    if (std::isfinite(trans_m))
      std::snprintf(buf, sizeof(buf), ", RE %g m %.3f m / %.3f deg",
                    evaluation::MetricNumber(r, {"distance_m"}), trans_m,
                    evaluation::MetricNumber(r, {"yaw_deg", "mean"}));
    else
      std::snprintf(buf, sizeof(buf), ", RE %g m: no segment", evaluation::MetricNumber(r, {"distance_m"}));
    s += buf;
  }
  const double nees_p = evaluation::MetricNumber(m, {"nees", "position", "mean"});
  if (std::isfinite(nees_p)) {
    std::snprintf(buf, sizeof(buf), ", NEES %.2f pos / %.2f rot (3 = consistent)", nees_p,
                  evaluation::MetricNumber(m, {"nees", "orientation", "mean"}));
    s += buf;
  }
  // A dropped marginalization prior (the window then holds only its own information) is said.
  const double failures_value = evaluation::MetricNumber(m, {"estimator", "marginalization_failures"});
  const int failures = std::isfinite(failures_value) ? static_cast<int>(failures_value) : 0;
  if (failures > 0)
    s += ", " + std::to_string(failures) + " failed marginalization" + (failures > 1 ? "s" : "") +
         " (prior dropped)";
  const nlohmann::json& detection = m.at("detection");
  s += ", detector " + detection.value("detector", std::string("none"));
  // Per-sample scores where the run knows the glitches (a detector that flags everything shows here).
  if (detection.contains("precision") && detection.value("detector", std::string("none")) != "none") {
    std::snprintf(buf, sizeof(buf), " (precision %.3f, recall %.3f, false positives %.2f %%)",
                  evaluation::MetricNumber(detection, {"precision"}),
                  evaluation::MetricNumber(detection, {"recall"}),
                  100.0 * evaluation::MetricNumber(detection, {"false_positive_rate"}));
    s += buf;
  }
  std::snprintf(buf, sizeof(buf), ", wall %.2f s", evaluation::MetricNumber(m, {"wall_time_s", "total"}));
  return s + buf;
}

}  // namespace vigil::experiments
