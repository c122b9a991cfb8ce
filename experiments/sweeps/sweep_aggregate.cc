#include "experiments/sweeps/sweep_aggregate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/output.h"
#include "evaluation/metrics_access.h"
#include "experiments/runs/run_metrics.h"
#include "experiments/runs/run_metrics_file.h"
#include "experiments/sweeps/sweep_engine.h"

namespace vigil::experiments {
namespace fs = std::filesystem;
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
double Ratio(double num, double den) { return den > 0 ? num / den : kNaN; }

// A run directory belongs to this plan only if the configuration it ran (its config.yaml, when it has one)
// is the plan's for its cell and seed: a sweep.yaml swapped for another sweep's is refused here, instead of
// tabulating runs under settings they did not run with. `planned` caches the cell's configuration.
// The dotted paths of a mapping's leaves ("evaluation.min_coverage").
std::vector<std::string> LeafKeys(const YAML::Node& node, const std::string& prefix = "") {
  std::vector<std::string> keys;
  for (const auto& entry : node) {
    const std::string key = prefix + entry.first.as<std::string>();
    if (entry.second.IsMap()) {
      const std::vector<std::string> inner = LeafKeys(entry.second, key + ".");
      keys.insert(keys.end(), inner.begin(), inner.end());
    } else {
      keys.push_back(key);
    }
  }
  return keys;
}

void CheckRunConfig(const fs::path& run_dir, const SweepSpec& spec, const SweepCell& cell, uint64_t seed,
                    std::optional<RunConfig>* planned) {
  const fs::path path = run_dir / "config.yaml";
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return;
  if (!*planned) *planned = ResolveCellConfig(spec, cell);
  RunConfig config = **planned;
  config.seed = seed;
  const std::string planned_yaml = config::ToYaml(config);
  const std::string written = ReadFile(path);
  if (written == planned_yaml) return;
  // A run of an earlier vigil lacks the keys added since (evaluation.min_coverage, ...). Its verdict was
  // given without them, so it is not mixed with this vigil's runs: say which keys, and how to go on.
  std::vector<std::string> absent;
  try {
    const YAML::Node old_root = YAML::Load(written);
    RunConfig old_config = LoadRunConfig(path.string());
    if (config::ToYaml(old_config) == planned_yaml)
      for (const std::string& key : LeafKeys(YAML::Load(planned_yaml)))
        if (config::KeyLine(old_root, key) == 0) absent.push_back(key);
  } catch (const std::exception&) {
    absent.clear();  // not a configuration this vigil reads: the refusal below
  }
  if (!absent.empty()) {
    std::string keys;
    for (const std::string& key : absent) keys += (keys.empty() ? "" : ", ") + key;
    throw InputError(path.string() + ": written by an earlier vigil, without " + keys +
                     " (its verdict was given without them); re-run the sweep into a new directory, or "
                     "with --force");
  }
  throw InputError(path.string() +
                   ": not the configuration the sweep's plan gives this run (sweep.yaml replaced, or the "
                   "run copied from another sweep); re-run the sweep, or restore its sweep.yaml");
}
}  // namespace

double CellResult::PooledReTrans(std::size_t d) const { return Ratio(re_trans_weighted[d], re_n[d]); }
double CellResult::PooledReYaw(std::size_t d) const { return Ratio(re_yaw_weighted[d], re_n[d]); }
double CellResult::Precision() const { return Ratio(true_flagged, flagged); }
double CellResult::Recall() const { return Ratio(true_flagged, glitched); }
double CellResult::FalsePositiveRate() const {
  return Ratio(scored_flagged - true_flagged, scored_samples - glitched);
}

void CellResult::Merge(const CellResult& o) {
  runs += o.runs;
  failed += o.failed;
  diverged += o.diverged;
  inconclusive += o.inconclusive;
  missing += o.missing;
  scored_samples += o.scored_samples;
  scored_flagged += o.scored_flagged;
  for (const auto& [reason, count] : o.failure_reasons) failure_reasons[reason] += count;
  ate_rmse_m.insert(ate_rmse_m.end(), o.ate_rmse_m.begin(), o.ate_rmse_m.end());
  if (re_n.size() < o.re_n.size()) {
    re_trans_weighted.resize(o.re_n.size(), 0.0);
    re_yaw_weighted.resize(o.re_n.size(), 0.0);
    re_n.resize(o.re_n.size(), 0.0);
    re_trans_run_means.resize(o.re_n.size());
  }
  for (std::size_t d = 0; d < o.re_n.size(); ++d) {
    re_trans_weighted[d] += o.re_trans_weighted[d];
    re_yaw_weighted[d] += o.re_yaw_weighted[d];
    re_n[d] += o.re_n[d];
    re_trans_run_means[d].insert(re_trans_run_means[d].end(), o.re_trans_run_means[d].begin(),
                                 o.re_trans_run_means[d].end());
  }
  flagged += o.flagged;
  glitched += o.glitched;
  true_flagged += o.true_flagged;
}

void AddRunMetrics(const nlohmann::json& m, const std::vector<double>& distances_m, CellResult* cell) {
  const std::size_t nd = distances_m.size();
  if (cell->re_n.size() != nd) {
    cell->re_trans_weighted.assign(nd, 0.0);
    cell->re_yaw_weighted.assign(nd, 0.0);
    cell->re_n.assign(nd, 0.0);
    cell->re_trans_run_means.assign(nd, {});
  }
  ++cell->runs;
  if (IsFailed(m)) {
    ++cell->failed;
    if (evaluation::MetricText(m, "status") == kInconclusive) ++cell->inconclusive;
    std::string reason = evaluation::MetricText(m, "failure_reason");
    ++cell->failure_reasons[reason.empty() ? "(no reason given)" : reason];
    return;
  }
  if (IsDiverged(m)) ++cell->diverged;
  const double ate = evaluation::MetricNumber(m, {"ate", "trans_m", "rmse"});
  if (std::isfinite(ate)) cell->ate_rmse_m.push_back(ate);
  for (std::size_t d = 0; d < nd; ++d) {
    const nlohmann::json* e = evaluation::RelativeEntry(m, distances_m[d]);
    if (!e) continue;
    const double n = evaluation::MetricNumber(*e, {"trans_m", "n"});
    const double trans = evaluation::MetricNumber(*e, {"trans_m", "mean"});
    const double yaw = evaluation::MetricNumber(*e, {"yaw_deg", "mean"});
    if (!(n > 0) || !std::isfinite(trans) || !std::isfinite(yaw)) continue;
    cell->re_trans_weighted[d] += trans * n;
    cell->re_yaw_weighted[d] += yaw * n;
    cell->re_n[d] += n;
    cell->re_trans_run_means[d].push_back(trans);
  }
  const double flagged = evaluation::MetricNumber(m, {"detection", "flagged_samples"});
  const double glitched = evaluation::MetricNumber(m, {"detection", "glitched_samples"});
  const double recall = evaluation::MetricNumber(m, {"detection", "recall"});
  if (std::isfinite(flagged)) cell->flagged += flagged;
  if (std::isfinite(glitched)) {
    cell->glitched += glitched;
    if (std::isfinite(recall)) cell->true_flagged += std::round(recall * glitched);
    const double samples = evaluation::MetricNumber(m, {"detection", "samples"});
    if (std::isfinite(samples) && std::isfinite(flagged)) {
      cell->scored_samples += samples;
      cell->scored_flagged += flagged;
    }
  }
}

int SweepAggregate::MethodIndex(const std::string& name) const {
  for (std::size_t m = 0; m < methods.size(); ++m)
    if (methods[m] == name) return static_cast<int>(m);
  return -1;
}

CellResult SweepAggregate::Pooled(std::size_t method) const {
  CellResult pooled;
  for (std::size_t g = 0; g < groups.size(); ++g) pooled.Merge(Cell(g, method));
  return pooled;
}

SweepAggregate AggregateSweep(const fs::path& dir, const SweepSpec& spec,
                              const std::vector<double>& distances_m, const RunVisitor& visit) {
  SweepAggregate agg;
  agg.distances_m = distances_m;
  for (const auto& m : spec.methods) agg.methods.push_back(m.label);
  const std::vector<SweepCell> cells = EnumerateCells(spec);
  for (std::size_t c = 0; c < cells.size(); c += spec.methods.size())
    agg.groups.push_back(CellGroupLabel(spec, cells[c]));
  agg.cells.resize(cells.size());
  for (auto& cell : agg.cells) {
    cell.re_trans_weighted.assign(distances_m.size(), 0.0);
    cell.re_yaw_weighted.assign(distances_m.size(), 0.0);
    cell.re_n.assign(distances_m.size(), 0.0);
    cell.re_trans_run_means.assign(distances_m.size(), {});
  }
  std::vector<std::optional<RunConfig>> planned_configs(cells.size());
  for (const SweepRunRef& run : EnumerateRuns(spec, cells)) {
    CellResult& cell = agg.cells[run.cell];  // cells are group-major, method fastest: the same order
    ++agg.runs;
    const fs::path path = RunMetricsPath(dir, run.id);
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
      ++cell.runs;
      ++cell.missing;
      ++agg.missing;
      agg.missing_ids.push_back(run.id);
      if (visit) visit(run, cells[run.cell], nullptr);
      continue;
    }
    const nlohmann::json metrics = ReadRunMetrics(path.string(), run.seed);
    CheckRunConfig(RunDirectory(dir, run.id), spec, cells[run.cell], run.seed, &planned_configs[run.cell]);
    AddRunMetrics(metrics, distances_m, &cell);
    if (IsFailed(metrics)) agg.failed_ids.push_back(run.id);
    if (IsDiverged(metrics)) agg.diverged_ids.push_back(run.id);
    if (visit) visit(run, cells[run.cell], &metrics);
  }
  return agg;
}

}  // namespace vigil::experiments
