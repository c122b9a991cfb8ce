// A whole sweep: resolve the grid, build the DTW templates, run everything through the engine, stream
// results.csv, and write the tables.
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
#include "experiments/run.h"
#include "experiments/sweep_engine.h"
#include "experiments/sweep_spec.h"

namespace vigil::experiments {

// Executes one run (ExecuteRun in production; tests inject fakes).
using RunExecutor =
    std::function<nlohmann::json(const RunConfig&, const RunOptions&, const std::filesystem::path&)>;

struct SweepRunOptions {
  int threads = 0;      // 0: every core
  bool resume = false;  // continue the sweep in `dir` (its sweep.yaml must be the same)
  bool force = false;   // start over in a non-empty `dir`
  std::FILE* progress = nullptr;
  bool write_tables = true;
};

// The template library of every cell that needs one (null for the others), in cell order.
struct SweepTemplates {
  std::vector<std::shared_ptr<const detectors::TemplateLibrary>> per_cell;
  std::size_t built = 0;  // distinct libraries built
};
SweepTemplates BuildSweepTemplates(const SweepSpec& spec, const std::vector<RunConfig>& cell_configs,
                                   const std::vector<bool>& needed, int threads);

// Runs `spec` into `dir`. InputError for bad input (a different sweep.yaml on --resume, a non-empty dir).
SweepOutcome RunSweep(const SweepSpec& spec, const std::filesystem::path& dir, const SweepRunOptions& options,
                      const RunExecutor& executor);

}  // namespace vigil::experiments
