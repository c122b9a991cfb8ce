#include "experiments/slurm/slurm_plan.h"

#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/error.h"
#include "core/output.h"
#include "experiments/sweeps/sweep_engine.h"
#include "experiments/sweeps/sweep_runner.h"
#include "experiments/sweeps/sweep_spec.h"

namespace vigil::experiments {
namespace {

namespace fs = std::filesystem;

// The first executable `name` on PATH (empty when there is none).
fs::path FindOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  std::size_t begin = 0;
  while (begin <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', begin), dirs.size());
    const fs::path candidate = fs::path(end > begin ? dirs.substr(begin, end - begin) : ".") / name;
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    begin = end + 1;
  }
  return {};
}

// Runs `argv` (no shell: argv[0] is the program's path) and returns its stdout; std::runtime_error when it
// cannot start or exits non-zero. At most 64 KiB of output is kept.
std::string RunAndCapture(const std::vector<std::string>& argv) {
  std::string shown;
  for (const std::string& word : argv) shown += (shown.empty() ? "" : " ") + ShellQuote(word);
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(shown + ": cannot create a pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  std::vector<char*> args;
  for (const std::string& word : argv) args.push_back(const_cast<char*>(word.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (spawned != 0) {
    ::close(fds[0]);
    throw std::runtime_error(shown + ": cannot start: " + std::strerror(spawned));
  }
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    if (out.size() < (64u << 10)) out.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(shown + ": failed (" +
                             (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                                : "signal " + std::to_string(WTERMSIG(status))) +
                             ")");
  return out;
}

void WriteScript(const fs::path& path, const std::string& text) {
  WriteFileAtomic(path, text);
  ::chmod(path.c_str(), 0755);
}

// The sweep the tasks run, and the `vigil` arguments that run it.
SweepSpec LoadRequestedSweep(const SlurmRequest& request, SlurmJobOptions* job) {
  const std::string sweep_file = fs::absolute(!request.paper                ? request.sweep
                                              : request.paper_sweep.empty() ? request.shipped_paper_sweep()
                                                                            : request.paper_sweep)
                                     .string();
  SweepSpec spec = LoadSweepSpec(sweep_file);
  if (request.paper) {
    SetSeedCount(&spec, static_cast<uint64_t>(request.seeds));
    job->sweep_arguments = {"paper", "--sweep", sweep_file, "--seeds", std::to_string(request.seeds)};
    job->tables_arguments = {"--figures"};
  } else {
    job->sweep_arguments = {"sweep", sweep_file};
  }
  return spec;
}

}  // namespace

SlurmJobPlan PlanSlurmJob(const SlurmRequest& request) {
  if (request.paper == !request.sweep.empty())
    throw InputError(request.paper ? "SWEEP: not with --paper (use --sweep to change the paper's sweep file)"
                                   : "SWEEP: required (a sweep file), or --paper");
  SlurmJobPlan plan;
  plan.sbatch = FindOnPath("sbatch");
  if (request.submit && plan.sbatch.empty())
    throw InputError(
        "--submit: sbatch is not on the PATH (is this a Slurm login node?); without --submit "
        "the scripts are written for you to submit");
  SlurmJobOptions& job = plan.job;
  const SweepSpec spec = LoadRequestedSweep(request, &job);
  job.vigil = request.vigil;
  job.dir = fs::absolute(request.output).lexically_normal();
  if (!job.dir.has_filename()) job.dir = job.dir.parent_path();
  job.tasks = request.tasks;
  job.cpus_per_task = request.cpus_per_task;
  job.partition = request.partition;
  job.time = request.time;
  job.job_name = "vigil-" + job.dir.filename().string();
  plan.scripts = MakeSlurmScripts(job);
  plan.resolved_sweep = ResolvedSweepYaml(spec);
  const SweepPlan sweep = ResolveSweepPlan(spec);
  plan.runs = sweep.runs.size();
  SweepRunOptions check;
  check.resume = true;  // a directory of the same sweep is fine: the tasks resume it
  CheckSweepOutput(job.dir, plan.resolved_sweep, check, sweep.runs);
  const std::vector<bool> all_cells(sweep.cells.size(), true);
  BuildSweepTemplates(spec, sweep.configs, all_cells, 0);  // what every task will build
  return plan;
}

void WriteSlurmJob(const SlurmJobPlan& plan) {
  PrepareSweepDirectory(plan.job.dir, /*resume=*/true, /*force=*/false);
  CommitSweepFile(plan.job.dir, plan.resolved_sweep);
  const fs::path slurm_dir = SlurmDirectory(plan.job.dir);
  fs::create_directories(slurm_dir);
  WriteScript(slurm_dir / "array.sbatch", plan.scripts.array);
  WriteScript(slurm_dir / "finalize.sbatch", plan.scripts.finalize);
  WriteScript(slurm_dir / "submit.sh", plan.scripts.submit);
}

SlurmJobIds SubmitSlurmJob(const SlurmJobPlan& plan) {
  const fs::path slurm_dir = SlurmDirectory(plan.job.dir);
  SlurmJobIds ids;
  ids.array = ParseSbatchJobId(
      RunAndCapture({plan.sbatch.string(), "--parsable", (slurm_dir / "array.sbatch").string()}));
  ids.finalize = ParseSbatchJobId(
      RunAndCapture({plan.sbatch.string(), "--parsable", "--dependency=afterany:" + ids.array,
                     (slurm_dir / "finalize.sbatch").string()}));
  return ids;
}

}  // namespace vigil::experiments
