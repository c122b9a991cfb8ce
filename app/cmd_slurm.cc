// `vigil slurm`: a sweep (or the paper's) as a Slurm job array of shards plus a finalize job; with --submit,
// submitted through sbatch. See experiments/slurm/slurm_plan.h and experiments/slurm/slurm_job.h for the
// scripts.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/config_dir.h"
#include "experiments/slurm/slurm_plan.h"

namespace vigil::app {
namespace fs = std::filesystem;

void AddSlurmCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "slurm",
      "write (and with --submit, submit) a Slurm job array running a sweep in shards plus a finalize job "
      "(vigil tables) into DIR/slurm/: array.sbatch, finalize.sbatch, submit.sh");
  auto args = std::make_shared<experiments::SlurmRequest>();
  cmd->add_option("SWEEP", args->sweep, "sweep file (YAML); not with --paper");
  cmd->add_option("-o,--output", args->output, "sweep directory (on a filesystem every node shares)")
      ->required();
  cmd->add_option("--tasks", args->tasks, "array tasks = shards of the plan")->required();
  cmd->add_option("--cpus-per-task", args->cpus_per_task, "CPUs of each task (its -j)")
      ->capture_default_str();
  cmd->add_option("--partition", args->partition, "Slurm partition (default: the cluster's)");
  cmd->add_option("--time", args->time, "time limit of each task (sbatch --time, e.g. 2:00:00)");
  auto* paper = cmd->add_flag("--paper", args->paper, "the paper's experiment (as vigil paper), not a SWEEP");
  cmd->add_option("--seeds", args->seeds, "with --paper: seeds per cell (1, 2, ... N)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->needs(paper);
  cmd->add_option(
         "--sweep", args->paper_sweep,
         "with --paper: the paper's sweep file (default: the shipped paper_sweep.yaml, as vigil paper)")
      ->needs(paper);
  cmd->add_flag("--submit", args->submit, "submit both jobs with sbatch and print their ids");
  SetAction(cmd, [args] {
    args->shipped_paper_sweep = [] { return ShippedConfig("paper_sweep.yaml"); };
    args->vigil = fs::canonical("/proc/self/exe");
    const experiments::SlurmJobPlan plan = experiments::PlanSlurmJob(*args);
    experiments::WriteSlurmJob(plan);
    const fs::path slurm_dir = experiments::SlurmDirectory(plan.job.dir);
    std::fprintf(stderr,
                 "vigil slurm: %zu runs in %d tasks of %d CPUs -> %s/{array.sbatch, finalize.sbatch, "
                 "submit.sh}\n",
                 plan.runs, plan.job.tasks, plan.job.cpus_per_task, slurm_dir.c_str());
    if (!args->submit) {
      std::fprintf(stderr, "vigil slurm: submit with %s\n", (slurm_dir / "submit.sh").c_str());
      return 0;
    }
    const experiments::SlurmJobIds ids = experiments::SubmitSlurmJob(plan);
    std::printf("%s\n%s\n", ids.array.c_str(), ids.finalize.c_str());
    std::fprintf(stderr, "vigil slurm: submitted array job %s (%d tasks) and finalize job %s; logs in %s\n",
                 ids.array.c_str(), plan.job.tasks, ids.finalize.c_str(), slurm_dir.c_str());
    return 0;
  });
}

}  // namespace vigil::app
