// Per-cell statistics of a sweep, read from its runs' metrics.json: what tables 2-4, summary.md and the
// regression gate are made of.
//
// A cell is (group, method): a group is one combination of axis settings (a column of table 2, e.g.
// "noise_50_10"). Errors are taken from the runs that finished (status ok or diverged: a diverged run's
// error is large but measured, and the means include it as they did before the verdict existed); failed
// runs are counted (with their reasons; inconclusive runs, whose errors rest on too little of the run, count
// as failed and are also counted apart), diverged runs are counted beside them, runs not on disk are counted
// as missing. Relative errors are pooled: the mean over every sub-trajectory of
// every run (each run's mean weighted by its number of sub-trajectories n), as when all segments of all runs
// are evaluated together. Detection precision/recall are pooled the same way (over samples).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/sweeps/sweep_spec.h"

namespace vigil::experiments {

struct CellResult {
  std::size_t runs = 0, failed = 0, diverged = 0, missing = 0;
  std::size_t inconclusive = 0;  // of the failed ones: status "inconclusive" (run_metrics.h)
  std::map<std::string, std::size_t> failure_reasons;  // reason -> count
  std::vector<double> ate_rmse_m;                      // one per successful run
  // Per distance (SweepAggregate::distances_m): sums of run mean x n, and of n.
  std::vector<double> re_trans_weighted, re_yaw_weighted, re_n;
  std::vector<std::vector<double>> re_trans_run_means;  // per distance, one per run (for std / median)
  double flagged = 0, glitched = 0, true_flagged = 0;   // detection, summed over runs
  // Samples and flagged samples of the runs scored against glitch labels (for the false-positive rate).
  double scored_samples = 0, scored_flagged = 0;

  std::size_t ok() const { return runs - failed - diverged - missing; }
  double PooledReTrans(std::size_t d) const;  // NaN without segments
  double PooledReYaw(std::size_t d) const;
  double Precision() const;          // NaN when nothing was flagged
  double Recall() const;             // NaN when nothing was glitched
  double FalsePositiveRate() const;  // flagged clean samples / clean samples; NaN without clean samples
  void Merge(const CellResult& other);
};

struct SweepAggregate {
  std::vector<std::string> groups;   // grid order
  std::vector<std::string> methods;  // spec order
  std::vector<double> distances_m;
  std::vector<CellResult> cells;  // groups.size() x methods.size(), group-major
  std::size_t runs = 0, missing = 0;
  std::vector<std::string> missing_ids, failed_ids, diverged_ids;  // plan order

  const CellResult& Cell(std::size_t group, std::size_t method) const {
    return cells[group * methods.size() + method];
  }
  int MethodIndex(const std::string& name) const;  // -1 when absent
  // Every group of one method pooled (tables 3 and 4).
  CellResult Pooled(std::size_t method) const;
};

// Adds one run's metrics to `cell`.
void AddRunMetrics(const nlohmann::json& metrics, const std::vector<double>& distances_m, CellResult* cell);

// Called for every run in plan order with its metrics (null when the run is not on disk).
using RunVisitor = std::function<void(const SweepRunRef&, const SweepCell&, const nlohmann::json*)>;

// Reads every run of the sweep in `dir` (spec = its sweep.yaml), one at a time. Absent runs count as missing.
SweepAggregate AggregateSweep(const std::filesystem::path& dir, const SweepSpec& spec,
                              const std::vector<double>& distances_m, const RunVisitor& visit = {});

}  // namespace vigil::experiments
