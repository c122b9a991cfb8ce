// The Monte Carlo engine: runs a list of independent runs in parallel (oneTBB), commits each one atomically
// and streams their results in plan order. It knows nothing about what a run does: the run function is
// injected (the sweep's real one calls ExecuteRun; tests use cheap fakes).
//
// Layout inside the sweep directory: runs/<id>/ with at least metrics.json. A run is written into a staging
// sibling runs/<id>.tmp-<host>-<pid>/ and renamed into place when complete, so runs/<id>/metrics.json exists
// exactly for finished runs, whatever happens to the process (kill -9 included). Several processes (shards,
// possibly on several machines) may run disjoint runs in one directory at once: at start only the staging of
// dead processes on this host is removed (core/staging.h), never that of a live or a remote one. With
// `resume`, finished runs are read back instead of executed; without it, the caller has emptied runs/ (see
// PrepareSweepDirectory).
//
// Failures: a run function that throws gives a committed metrics.json {"status": "failed", "failure_reason":
// what()}; a run whose metrics say "failed" (e.g. the estimator diverged) counts as failed too; the sweep
// goes on either way. Determinism: each run must depend on its index only (not on timing or thread), which
// makes every result identical for any thread count. Memory: a bounded number of runs is in flight
// (4 x threads); results leave through `on_result` in plan order and are not kept.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vigil::experiments {

// Runs run `index` and writes its files into `dir` (existing, empty); returns its metrics (metrics.json).
// metrics.json itself is written by the engine from the returned document.
using RunFunction = std::function<nlohmann::json(std::size_t index, const std::filesystem::path& dir)>;

// Receives every run's metrics (as committed on disk) in plan order, from one thread at a time.
using ResultFunction = std::function<void(std::size_t index, const nlohmann::json& metrics)>;

struct SweepEngineOptions {
  int threads = 0;                // 0: every core
  bool resume = false;            // read finished runs back instead of executing them
  std::FILE* progress = nullptr;  // progress bar stream (null: none)
};

struct SweepOutcome {
  std::size_t total = 0, executed = 0, resumed = 0, failed = 0;
  double wall_time_s = 0.0;
};

// Status of a metrics document: true unless "status" is "ok" or "diverged" (a run that finished with an
// error beyond the divergence bound: its errors still count, run_metrics.h).
bool IsFailed(const nlohmann::json& metrics);
// True when "status" is "diverged".
bool IsDiverged(const nlohmann::json& metrics);

// The run directory of `id` and the file that marks it finished.
std::filesystem::path RunDirectory(const std::filesystem::path& sweep_dir, const std::string& id);
std::filesystem::path RunMetricsPath(const std::filesystem::path& sweep_dir, const std::string& id);

// Runs every id of `run_ids` (plan order) inside `sweep_dir` (existing). Throws only on I/O errors.
SweepOutcome ExecuteSweep(const std::filesystem::path& sweep_dir, const std::vector<std::string>& run_ids,
                          const RunFunction& run, const ResultFunction& on_result,
                          const SweepEngineOptions& options);

// The checks of PrepareSweepDirectory, without writing anything: an existing non-empty `dir` is refused
// (InputError) unless it holds a sweep (sweep.yaml) and `resume` or `force` is given.
void CheckSweepDirectory(const std::filesystem::path& dir, bool resume, bool force);

// Prepares `dir` for a sweep: creates it; an existing non-empty one is refused (InputError) unless `resume`
// (kept as is: finished runs stay) or `force` (the previous sweep's runs/ and result files are removed).
void PrepareSweepDirectory(const std::filesystem::path& dir, bool resume, bool force);

}  // namespace vigil::experiments
