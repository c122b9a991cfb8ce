// A whole sweep: resolve the grid, build the DTW templates, run everything through the engine, stream
// results.csv and timing.csv, and hand the aggregate to the table writer (the report library's
// report::WriteTableFiles in `vigil sweep`; experiments/ never includes the report library).
//
// Nothing is written before the whole plan is valid: every cell's configuration, every run id, the
// directory rules (core/output.h, PrepareSweepDirectory) and the DTW template builds are checked first, so a
// sweep refused for bad input leaves no file behind.
//
// Shards (experiments/sweeps/sweep_shard.h): with a shard other than the whole sweep, only that shard's runs
// are executed, and nothing but run directories is written besides DIR/sweep.yaml (created by the first
// shard, atomically; every other one checks that its sweep is the same): no results.csv, timing.csv or
// tables, which `vigil tables DIR` writes once every shard is done. Shards may run at the same time, on
// several machines sharing the directory. A shard whose runs are already there needs `resume` (finished runs
// kept); `force` would remove the other shards' runs and is refused.
//
// DTW templates: for every cell whose method is `dtw` without a templates_file, a library is built from a
// glitch-free simulation of that cell's scenario with seed spec.template_seed (never a run seed) and shared
// by its runs (RunOptions::templates). Cells whose scenario and DTW build options are the same (e.g. the
// three glitch settings of the paper, which differ only in glitches) share one library, built once.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "detectors/template_library.h"
#include "experiments/runs/run.h"
#include "experiments/sweeps/sweep_aggregate.h"
#include "experiments/sweeps/sweep_engine.h"
#include "experiments/sweeps/sweep_shard.h"
#include "experiments/sweeps/sweep_spec.h"

namespace vigil::experiments {

// Executes one run (ExecuteRun in production; tests inject fakes).
using RunExecutor =
    std::function<nlohmann::json(const RunConfig&, const RunOptions&, const std::filesystem::path&)>;

// Writes the tables of a whole sweep in `dir` from its committed runs (`spec`: the sweep.yaml written there).
using TableWriter =
    std::function<void(const std::filesystem::path& dir, const SweepSpec& spec, const SweepAggregate& agg)>;

struct SweepRunOptions {
  int threads = 0;      // 0: every core
  bool resume = false;  // continue the sweep in `dir` (its sweep.yaml must be the same)
  bool force = false;   // start over in a non-empty `dir`
  std::FILE* progress = nullptr;
  TableWriter write_tables;  // empty: no tables (results.csv and timing.csv only)
  SweepShard shard;          // the whole sweep by default
};

// The template library of every cell that needs one (null for the others), in cell order.
struct SweepTemplates {
  std::vector<std::shared_ptr<const detectors::TemplateLibrary>> per_cell;
  std::size_t built = 0;  // distinct libraries built
};
SweepTemplates BuildSweepTemplates(const SweepSpec& spec, const std::vector<RunConfig>& cell_configs,
                                   const std::vector<bool>& needed, int threads);

// The resolved plan of a sweep: cells, their configurations (validated) and runs, in plan order.
struct SweepPlan {
  std::vector<SweepCell> cells;
  std::vector<RunConfig> configs;  // one per cell
  std::vector<SweepRunRef> runs;
};
SweepPlan ResolveSweepPlan(const SweepSpec& spec);

// The checks RunSweep makes of `dir` before writing anything (`shard_runs`: the runs it would execute);
// InputError when refused. Then CommitSweepFile writes DIR/sweep.yaml (`resolved`, ResolvedSweepYaml) unless
// a concurrent shard did, and refuses a different one.
void CheckSweepOutput(const std::filesystem::path& dir, const std::string& resolved,
                      const SweepRunOptions& options, const std::vector<SweepRunRef>& shard_runs);
void CommitSweepFile(const std::filesystem::path& dir, const std::string& resolved);

// Runs `spec` (or its options.shard) into `dir`. InputError for bad input (a different sweep.yaml in `dir`,
// a non-empty directory that is not this sweep's, a configuration or template build that cannot work).
SweepOutcome RunSweep(const SweepSpec& spec, const std::filesystem::path& dir, const SweepRunOptions& options,
                      const RunExecutor& executor);

}  // namespace vigil::experiments
