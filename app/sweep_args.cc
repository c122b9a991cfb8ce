#include "app/sweep_args.h"

#include <unistd.h>

#include <cstdio>

#include "core/error.h"
#include "core/output.h"
#include "experiments/runs/run.h"
#include "experiments/sweeps/progress.h"
#include "experiments/sweeps/sweep_runner.h"
#include "report/tables.h"

namespace vigil::app {

void SweepArgs::AddTo(CLI::App* cmd) {
  cmd->add_option("-o,--output", output,
                  "sweep directory to write (runs/, results.csv, timing.csv, tables, summary.md); required "
                  "unless --list");
  cmd->add_option("-j,--jobs", threads,
                  "runs in parallel, 1 .. " + std::to_string(kMaxJobs) +
                      " (default or 0: every core); each run is single-threaded")
      ->check(CLI::Range(0, kMaxJobs));
  auto* resume_flag = cmd->add_flag(
      "--resume", resume, "continue an interrupted sweep in the output directory (finished runs kept)");
  cmd->add_flag("--force", force, "start over in a non-empty output directory (removes its runs/ and tables)")
      ->excludes(resume_flag);
  cmd->add_option(
         "--shard", shard,
         "run only shard I of N (0 <= I < N: the runs whose plan index is I modulo N); shards may run "
         "at once into one directory, `vigil tables DIR` merges them")
      ->type_name("I/N");
  cmd->add_flag("--list", list, "print the plan's run ids (of the --shard), one per line in order, and exit");
  cmd->add_flag("-q,--quiet", quiet, "no progress bar and no closing line");
}

experiments::SweepShard SweepArgs::Shard() const {
  return shard.empty() ? experiments::SweepShard{} : experiments::ParseShard(shard);
}

int SweepArgs::Run(const experiments::SweepSpec& spec, const char* command) const {
  const experiments::SweepShard part = Shard();
  if (list) {
    const experiments::SweepPlan plan = experiments::ResolveSweepPlan(spec);
    for (const auto& run : experiments::ShardRuns(plan.runs, part)) std::printf("%s\n", run.id.c_str());
    return 0;
  }
  if (output.empty()) throw InputError("--output: required (the sweep directory), unless --list");
  // The sweep file (unless it is the directory's own sweep.yaml, the record of this very sweep), its base
  // configuration and every file a cell's configuration reads.
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> inputs{spec.base};
  if (fs::weakly_canonical(fs::absolute(spec.path), ec) !=
      fs::weakly_canonical(fs::absolute(output) / "sweep.yaml", ec))
    inputs.emplace_back(spec.path);
  for (const experiments::SweepCell& cell : experiments::EnumerateCells(spec))
    for (const auto& file : experiments::RunConfigInputs(experiments::ResolveCellConfig(spec, cell)))
      inputs.emplace_back(file);
  RefuseOutputOverInputs(output, inputs);
  experiments::SweepRunOptions options;
  options.threads = threads;
  options.resume = resume;
  options.force = force;
  options.shard = part;
  options.write_tables = report::WriteTableFiles;
  options.progress = !quiet && ::isatty(STDERR_FILENO) ? stderr : nullptr;
  const experiments::SweepOutcome o = experiments::RunSweep(spec, output, options, experiments::ExecuteRun);
  if (quiet) return 0;
  const std::string duration = experiments::FormatDuration(o.wall_time_s);
  if (part.whole())
    std::fprintf(stderr,
                 "vigil %s: %zu runs (%zu executed, %zu resumed), %zu failed, %s -> %s/{results.csv, "
                 "timing.csv, table2-4.{md,csv,tex}, summary.md}\n",
                 command, o.total, o.executed, o.resumed, o.failed, duration.c_str(), output.c_str());
  else
    std::fprintf(stderr,
                 "vigil %s: shard %s: %zu runs (%zu executed, %zu resumed), %zu failed, %s -> %s/runs/ "
                 "(`vigil tables %s` merges the shards)\n",
                 command, part.Label().c_str(), o.total, o.executed, o.resumed, o.failed, duration.c_str(),
                 output.c_str(), output.c_str());
  return 0;
}

}  // namespace vigil::app
