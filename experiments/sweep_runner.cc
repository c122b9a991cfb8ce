#include "experiments/sweep_runner.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/error.h"
#include "core/output.h"
#include "experiments/detection_stage.h"
#include "experiments/results_csv.h"
#include "experiments/tables.h"

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
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, sources.size(), [&](std::size_t k) {
      libraries[k] = std::make_shared<detectors::TemplateLibrary>(BuildTemplatesFromGlitchFreeSimulation(
          sources[k]->sim, sources[k]->detector.dtw, spec.template_seed));
    });
  });
  SweepTemplates out;
  out.built = libraries.size();
  out.per_cell.resize(cell_configs.size());
  for (std::size_t c = 0; c < cell_configs.size(); ++c)
    if (cell_key[c] >= 0) out.per_cell[c] = libraries[static_cast<std::size_t>(cell_key[c])];
  return out;
}

SweepOutcome RunSweep(const SweepSpec& spec, const fs::path& dir, const SweepRunOptions& options,
                      const RunExecutor& executor) {
  const std::string resolved = ResolvedSweepYaml(spec);
  const fs::path sweep_file = dir / "sweep.yaml";
  std::error_code ec;
  if (options.resume && fs::is_regular_file(sweep_file, ec) && ReadFile(sweep_file) != resolved)
    throw InputError(sweep_file.string() +
                     ": a different sweep was started in this directory (use --force to start over)");
  PrepareSweepDirectory(dir, options.resume, options.force);
  WriteFileAtomic(sweep_file, resolved);

  const std::vector<SweepCell> cells = EnumerateCells(spec);
  std::vector<RunConfig> configs;
  configs.reserve(cells.size());
  for (const SweepCell& cell : cells) configs.push_back(ResolveCellConfig(spec, cell));
  const std::vector<SweepRunRef> runs = EnumerateRuns(spec, cells);

  std::vector<bool> needed(cells.size(), false);
  for (const SweepRunRef& run : runs)
    if (!options.resume || !fs::is_regular_file(RunMetricsPath(dir, run.id), ec)) needed[run.cell] = true;
  const SweepTemplates templates = BuildSweepTemplates(spec, configs, needed, options.threads);

  std::vector<std::string> ids;
  ids.reserve(runs.size());
  for (const auto& run : runs) ids.push_back(run.id);

  ResultsCsvWriter csv(dir, spec, configs.front().evaluation.distances_m);
  SweepEngineOptions engine;
  engine.threads = options.threads;
  engine.resume = options.resume;
  engine.progress = options.progress;
  const SweepOutcome outcome = ExecuteSweep(
      dir, ids,
      [&](std::size_t index, const fs::path& run_dir) {
        const SweepRunRef& run = runs[index];
        RunConfig config = configs[run.cell];
        config.seed = run.seed;
        RunOptions run_options;
        run_options.write_trajectories = spec.write_trajectories;
        run_options.write_figure_data = spec.write_figure_data;
        run_options.templates = templates.per_cell[run.cell].get();
        return executor(config, run_options, run_dir);
      },
      [&](std::size_t index, const nlohmann::json& metrics) {
        csv.Add(runs[index], cells[runs[index].cell], metrics);
      },
      engine);
  csv.Commit();  // streamed in plan order above; the tables come from the same committed runs
  if (options.write_tables) {
    const SweepSpec written = LoadSweepSpec(sweep_file.string());  // summary.md names DIR/sweep.yaml
    WriteTableFiles(dir, written, AggregateSweep(dir, written, configs.front().evaluation.distances_m));
  }
  return outcome;
}

}  // namespace vigil::experiments
