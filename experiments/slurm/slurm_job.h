// A sweep as a Slurm job array (`vigil slurm`): the scripts, written into DIR/slurm/.
//
//   array.sbatch     one task per shard: task I runs `vigil sweep SWEEP -o DIR --shard I/N --resume -j C`
//                    (or the `vigil paper` equivalent). N is written into the script, never read from Slurm:
//                    a task resubmitted alone (`sbatch --array=1 array.sbatch`) sees
//                    SLURM_ARRAY_TASK_COUNT=1.
//                    --resume makes a requeued or resubmitted task finish its shard, keeping its finished
//                    runs; a task killed mid-run leaves only staging (runs/<id>.tmp-<host>-<pid>/), never a
//                    half run. Logs: DIR/slurm/<array job id>_<task>.log.
//   finalize.sbatch  `vigil tables DIR` (the paper: `--figures` too), submitted with --dependency=afterany on
//                    the array, so it runs whatever the tasks' fate and reports missing or failed runs.
//   submit.sh        submits both and prints the two job ids: what `vigil slurm --submit` does.
//
// Every path in the scripts is absolute (the directory and the vigil binary must be on a filesystem every
// node shares).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vigil::experiments {

struct SlurmJobOptions {
  std::filesystem::path vigil;  // the vigil binary (absolute)
  std::filesystem::path dir;    // the sweep directory (absolute)
  std::vector<std::string>
      sweep_arguments;  // after `vigil`, without -o/--shard/--resume/-j (e.g. sweep FILE)
  std::vector<std::string> tables_arguments;  // after `vigil tables DIR` (e.g. --figures)
  int tasks = 1;
  int cpus_per_task = 1;
  std::string partition;  // empty: the cluster's default
  std::string time;       // empty: the partition's default (sbatch --time syntax, e.g. 2:00:00)
  std::string job_name;
};

struct SlurmScripts {
  std::string array, finalize, submit;
};

// Quotes one word for bash ('...' with ' written as '\'').
std::string ShellQuote(const std::string& word);

// Bounds of the array (docs/safety.md): Slurm's own MaxArraySize is far smaller by default (1001).
inline constexpr int kMaxSlurmTasks = 100000;
inline constexpr int kMaxSlurmCpusPerTask = 256;

// InputError for options sbatch would refuse: tasks outside [1, kMaxSlurmTasks], cpus outside
// [1, kMaxSlurmCpusPerTask], a partition with spaces or quotes, a time that is not sbatch --time syntax
// (MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS, UNLIMITED or INFINITE).

void ValidateSlurmJobOptions(const SlurmJobOptions& options);

SlurmScripts MakeSlurmScripts(const SlurmJobOptions& options);

// The job id in what `sbatch --parsable` printed: "1234" or "1234;cluster" (surrounding blank space
// ignored) gives "1234"; anything else (empty, other text, a second line) is a std::runtime_error naming
// what sbatch printed, sanitized to one line.
std::string ParseSbatchJobId(const std::string& parsable);

// The directory of the scripts and logs: DIR/slurm.
std::filesystem::path SlurmDirectory(const std::filesystem::path& sweep_dir);

}  // namespace vigil::experiments
