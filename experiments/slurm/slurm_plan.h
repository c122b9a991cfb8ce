// `vigil slurm` without the process: a sweep (or the paper's) planned as a Slurm job array of shards plus a
// finalize job (experiments/slurm/slurm_job.h), written into DIR/slurm/, and submitted through sbatch as a
// separate step.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

#include "experiments/slurm/slurm_job.h"

namespace vigil::experiments {

struct SlurmRequest {
  std::string sweep;   // the sweep file; empty with `paper`
  std::string output;  // the sweep directory (on a filesystem every node shares)
  int tasks = 0, cpus_per_task = 1;
  std::string partition, time;  // empty: the cluster's defaults
  bool paper = false;           // the paper's experiment (as `vigil paper`), not a sweep file
  long long seeds = 10;         // with `paper`: seeds per cell
  std::string paper_sweep;      // with `paper`: its sweep file; empty: shipped_paper_sweep()
  std::function<std::string()> shipped_paper_sweep;  // called only when needed
  bool submit = false;                               // the plan must find sbatch on the PATH
  std::filesystem::path vigil;                       // the binary the scripts run (absolute)
};

struct SlurmJobPlan {
  SlurmJobOptions job;
  SlurmScripts scripts;
  std::string resolved_sweep;  // DIR/sweep.yaml
  std::size_t runs = 0;
  std::filesystem::path sbatch;  // sbatch on the PATH; empty when there is none
};

// Everything that can be refused, before anything is written: SWEEP xor paper, sbatch on the PATH when
// `submit`, the sweep file, the job options, a sweep directory of another sweep (one of the same sweep is
// fine: the tasks resume it) and the DTW template builds every task will run.
SlurmJobPlan PlanSlurmJob(const SlurmRequest& request);

// DIR/sweep.yaml and DIR/slurm/{array.sbatch, finalize.sbatch, submit.sh} (executable).
void WriteSlurmJob(const SlurmJobPlan& plan);

struct SlurmJobIds {
  std::string array, finalize;
};

// Submits the array, then the finalize job with --dependency=afterany on it, through plan.sbatch (run
// without a shell; only a job id it printed goes into the next command). std::runtime_error when sbatch
// cannot start, fails, or prints no job id.
SlurmJobIds SubmitSlurmJob(const SlurmJobPlan& plan);

}  // namespace vigil::experiments
