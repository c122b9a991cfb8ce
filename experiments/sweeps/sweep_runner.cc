#include "experiments/sweeps/sweep_runner.h"

#include <memory>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/error.h"
#include "core/output.h"
#include "core/staging.h"
#include "core/thread_handoff.h"
#include "experiments/runs/detection_stage.h"
#include "experiments/runs/external_estimator.h"
#include "experiments/sweeps/results_csv.h"
#include "experiments/sweeps/sweep_lock.h"

namespace vigil::experiments {
namespace fs = std::filesystem;

SweepTemplates BuildSweepTemplates(const SweepSpec& spec, const std::vector<RunConfig>& cell_configs,
                                   const std::vector<bool>& needed, int threads) {
  // Distinct (glitch-free scenario, DTW build options) keys, in first-use order.
  std::map<std::string, std::size_t> key_index;
  std::vector<const RunConfig*> sources;
  std::vector<int> cell_key(cell_configs.size(), -1);
  for (std::size_t c = 0; c < cell_configs.size(); ++c) {
    const RunConfig& config = cell_configs[c];
    if (!needed[c] || config.detector.type != detectors::DetectorType::kDtw ||
        !config.detector.dtw.templates_file.empty())
      continue;
    sim::SimOptions scenario = config.sim;
    scenario.glitch = sim::GlitchOptions{};  // glitch-free: the glitch settings do not matter
    detectors::DtwOptions dtw = config.detector.dtw;
    const std::string key = config::ToYaml(scenario) + config::ToYaml(dtw);
    const auto [it, inserted] = key_index.emplace(key, sources.size());
    if (inserted) sources.push_back(&config);
    cell_key[c] = static_cast<int>(it->second);
  }
  std::vector<std::shared_ptr<const detectors::TemplateLibrary>> libraries(sources.size());
  std::vector<std::string> errors(sources.size());
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  const int handoff = 0;  // hands what was written before to the bodies, and each body's k back (TSan)
  HandOffRelease(&handoff);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, sources.size(), [&](std::size_t k) {
      HandOffAcquire(&handoff);
      try {
        libraries[k] = std::make_shared<detectors::TemplateLibrary>(BuildTemplatesFromGlitchFreeSimulation(
            sources[k]->sim, sources[k]->detector.dtw, spec.template_seed));
      } catch (const InputError& e) {
        errors[k] = e.what();
      }
      HandOffRelease(&libraries[k]);
    });
  });
  for (std::size_t k = 0; k < sources.size(); ++k) HandOffAcquire(&libraries[k]);
  // A library that cannot be built: the error names the sweep-file line of the first cell that needs it.
  const std::vector<SweepCell> cells = EnumerateCells(spec);
  for (std::size_t c = 0; c < cell_configs.size(); ++c)
    if (cell_key[c] >= 0 && !errors[static_cast<std::size_t>(cell_key[c])].empty())
      ThrowCellError(spec, cells[c], errors[static_cast<std::size_t>(cell_key[c])]);
  SweepTemplates out;
  out.built = libraries.size();
  out.per_cell.resize(cell_configs.size());
  for (std::size_t c = 0; c < cell_configs.size(); ++c)
    if (cell_key[c] >= 0) out.per_cell[c] = libraries[static_cast<std::size_t>(cell_key[c])];
  return out;
}

SweepPlan ResolveSweepPlan(const SweepSpec& spec) {
  SweepPlan plan;
  plan.cells = EnumerateCells(spec);
  plan.configs.reserve(plan.cells.size());
  for (const SweepCell& cell : plan.cells) {
    plan.configs.push_back(ResolveCellConfig(spec, cell));
    // A sweep's runs are simulated: feature tracks, no camera images on disk.
    if (const std::string why = ExternalInputProblem(plan.configs.back(), false, true); !why.empty())
      ThrowCellError(spec, cell, why);
    // A recording (or any input file) that is absent would fail every run of the cell: refused before any.
    if (const std::string why = MissingInputProblem(plan.configs.back()); !why.empty())
      ThrowCellError(spec, cell, why);
  }
  plan.runs = EnumerateRuns(spec, plan.cells);
  return plan;
}

void CheckSweepOutput(const fs::path& dir, const std::string& resolved, const SweepRunOptions& options,
                      const std::vector<SweepRunRef>& runs) {
  const fs::path sweep_file = dir / "sweep.yaml";
  const bool sharded = !options.shard.whole();
  if (sharded && options.force)
    throw InputError("--force: cannot be used with --shard " + options.shard.Label() +
                     " (it would remove the other shards' runs); use --resume, or a new directory");
  // Shards share the directory: one that holds the same sweep is expected, whoever started it.
  std::error_code ec;
  const bool has_sweep = fs::is_regular_file(sweep_file, ec);
  const bool same_sweep = has_sweep && ReadFile(sweep_file) == resolved;
  if ((options.resume || sharded) && has_sweep && !same_sweep)
    throw InputError(sweep_file.string() +
                     ": a different sweep was started in this directory (the sweep file or its options "
                     "changed since); use a new directory" +
                     (sharded ? "" : ", or --force to start over"));
  CheckSweepDirectory(dir, options.resume || (sharded && same_sweep), options.force);
  if (sharded && !options.resume) {
    std::size_t finished = 0;
    for (const SweepRunRef& run : runs) finished += fs::is_regular_file(RunMetricsPath(dir, run.id), ec);
    if (finished > 0)
      throw InputError(dir.string() + ": shard " + options.shard.Label() + " already has " +
                       std::to_string(finished) + " finished runs here (use --resume to continue it)");
  }
}

void CommitSweepFile(const fs::path& dir, const std::string& resolved) {
  const fs::path sweep_file = dir / "sweep.yaml";
  std::error_code ec;
  if (fs::is_regular_file(sweep_file, ec) && ReadFile(sweep_file) == resolved) return;
  if (!WriteFileIfAbsent(sweep_file, resolved) && ReadFile(sweep_file) != resolved)
    throw InputError(sweep_file.string() +
                     ": a different sweep was started in this directory at the same time");
}

SweepOutcome RunSweep(const SweepSpec& spec, const fs::path& dir, const SweepRunOptions& options,
                      const RunExecutor& executor) {
  // 1. Everything that can be refused, before the first byte is written.
  const std::string resolved = ResolvedSweepYaml(spec);
  const SweepPlan plan = ResolveSweepPlan(spec);
  const std::vector<SweepRunRef> runs = ShardRuns(plan.runs, options.shard);
  CheckSweepOutput(dir, resolved, options, runs);
  std::error_code ec;
  const bool keep_finished = options.resume || !options.shard.whole();
  std::vector<bool> needed(plan.cells.size(), false);
  for (const SweepRunRef& run : runs)
    if (!keep_finished || !fs::is_regular_file(RunMetricsPath(dir, run.id), ec)) needed[run.cell] = true;
  const SweepTemplates templates = BuildSweepTemplates(spec, plan.configs, needed, options.threads);

  // 2. The directory, under the sweep's lock (a whole sweep alone, shards together), checked again now that
  // no other sweep can change it; then sweep.yaml and the runs.
  const SweepDirectoryLock lock(dir, options.shard.whole());
  CheckSweepOutput(dir, resolved, options, runs);
  PrepareSweepDirectory(dir, keep_finished, options.force);
  CommitSweepFile(dir, resolved);
  RemoveStaleStaging(dir);  // results.csv.tmp-... of a killed sweep on this host

  std::vector<std::string> ids;
  ids.reserve(runs.size());
  for (const auto& run : runs) ids.push_back(run.id);
  const std::vector<double>& distances = plan.configs.front().evaluation.distances_m;
  std::unique_ptr<ResultsCsvWriter> csv;
  if (options.shard.whole()) csv = std::make_unique<ResultsCsvWriter>(dir, spec, distances);
  SweepEngineOptions engine;
  engine.threads = options.threads;
  engine.resume = keep_finished;
  engine.progress = options.progress;
  const SweepOutcome outcome = ExecuteSweep(
      dir, ids,
      [&](std::size_t index, const fs::path& run_dir) {
        const SweepRunRef& run = runs[index];
        RunConfig config = plan.configs[run.cell];
        config.seed = run.seed;
        RunOptions run_options;
        run_options.write_trajectories = spec.write_trajectories;
        run_options.write_figure_data = spec.write_figure_data;
        run_options.templates = templates.per_cell[run.cell].get();
        return executor(config, run_options, run_dir);
      },
      [&](std::size_t index, const nlohmann::json& metrics) {
        if (csv) csv->Add(runs[index], plan.cells[runs[index].cell], metrics);
      },
      engine);
  if (!csv) return outcome;  // a shard: `vigil tables DIR` merges every shard's runs
  csv->Commit();             // streamed in plan order above; the tables come from the same committed runs
  if (options.write_tables) {
    const SweepSpec written = LoadSweepSpec((dir / "sweep.yaml").string());
    options.write_tables(dir, written, AggregateSweep(dir, written, distances));
  }
  return outcome;
}

}  // namespace vigil::experiments
