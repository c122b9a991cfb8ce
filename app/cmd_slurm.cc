// `vigil slurm`: a sweep (or the paper's) as a Slurm job array of shards plus a finalize job; with --submit,
// submitted through sbatch. See experiments/slurm_job.h for the scripts.
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/config_dir.h"
#include "core/error.h"
#include "core/output.h"
#include "experiments/slurm_job.h"
#include "experiments/sweep_runner.h"

namespace vigil::app {
namespace fs = std::filesystem;
namespace {

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
  for (const std::string& word : argv) shown += (shown.empty() ? "" : " ") + experiments::ShellQuote(word);
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

}  // namespace

void AddSlurmCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "slurm",
      "write (and with --submit, submit) a Slurm job array running a sweep in shards plus a finalize job "
      "(vigil tables) into DIR/slurm/: array.sbatch, finalize.sbatch, submit.sh");
  struct Args {
    std::string sweep, output, partition, time;
    int tasks = 0, cpus = 1;
    bool submit = false, paper = false;
    long long seeds = 10;
    std::string paper_sweep;  // empty: the shipped paper_sweep.yaml (app/config_dir.h)
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("SWEEP", args->sweep, "sweep file (YAML); not with --paper");
  cmd->add_option("-o,--output", args->output, "sweep directory (on a filesystem every node shares)")
      ->required();
  cmd->add_option("--tasks", args->tasks, "array tasks = shards of the plan")->required();
  cmd->add_option("--cpus-per-task", args->cpus, "CPUs of each task (its -j)")->capture_default_str();
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
    // 1. Everything that can be refused, before anything is written.
    if (args->paper == !args->sweep.empty())
      throw InputError(args->paper ? "SWEEP: not with --paper (use --sweep to change the paper's sweep file)"
                                   : "SWEEP: required (a sweep file), or --paper");
    const fs::path sbatch = FindOnPath("sbatch");
    if (args->submit && sbatch.empty())
      throw InputError(
          "--submit: sbatch is not on the PATH (is this a Slurm login node?); without --submit "
          "the scripts are written for you to submit");
    const std::string sweep_file =
        fs::absolute(!args->paper                ? args->sweep
                     : args->paper_sweep.empty() ? ShippedConfig("paper_sweep.yaml")
                                                 : args->paper_sweep)
            .string();
    experiments::SweepSpec spec = experiments::LoadSweepSpec(sweep_file);
    experiments::SlurmJobOptions job;
    if (args->paper) {
      experiments::SetSeedCount(&spec, static_cast<uint64_t>(args->seeds));
      job.sweep_arguments = {"paper", "--sweep", sweep_file, "--seeds", std::to_string(args->seeds)};
      job.tables_arguments = {"--figures"};
    } else {
      job.sweep_arguments = {"sweep", sweep_file};
    }
    job.vigil = fs::canonical("/proc/self/exe");
    job.dir = fs::absolute(args->output).lexically_normal();
    if (!job.dir.has_filename()) job.dir = job.dir.parent_path();
    job.tasks = args->tasks;
    job.cpus_per_task = args->cpus;
    job.partition = args->partition;
    job.time = args->time;
    job.job_name = "vigil-" + job.dir.filename().string();
    const experiments::SlurmScripts scripts = experiments::MakeSlurmScripts(job);
    const std::string resolved = experiments::ResolvedSweepYaml(spec);
    const experiments::SweepPlan plan = experiments::ResolveSweepPlan(spec);
    experiments::SweepRunOptions check;
    check.resume = true;  // a directory of the same sweep is fine: the tasks resume it
    experiments::CheckSweepOutput(job.dir, resolved, check, plan.runs);
    const std::vector<bool> all_cells(plan.cells.size(), true);
    experiments::BuildSweepTemplates(spec, plan.configs, all_cells, 0);  // what every task will build

    // 2. DIR/sweep.yaml and DIR/slurm/.
    experiments::PrepareSweepDirectory(job.dir, /*resume=*/true, /*force=*/false);
    experiments::CommitSweepFile(job.dir, resolved);
    const fs::path slurm_dir = experiments::SlurmDirectory(job.dir);
    fs::create_directories(slurm_dir);
    WriteScript(slurm_dir / "array.sbatch", scripts.array);
    WriteScript(slurm_dir / "finalize.sbatch", scripts.finalize);
    WriteScript(slurm_dir / "submit.sh", scripts.submit);
    std::fprintf(stderr,
                 "vigil slurm: %zu runs in %d tasks of %d CPUs -> %s/{array.sbatch, finalize.sbatch, "
                 "submit.sh}\n",
                 plan.runs.size(), job.tasks, job.cpus_per_task, slurm_dir.c_str());
    if (!args->submit) {
      std::fprintf(stderr, "vigil slurm: submit with %s\n", (slurm_dir / "submit.sh").c_str());
      return 0;
    }

    // 3. Submission.
    // sbatch runs without a shell, and only a job id it printed goes into the next command.
    const std::string array = experiments::ParseSbatchJobId(
        RunAndCapture({sbatch.string(), "--parsable", (slurm_dir / "array.sbatch").string()}));
    const std::string finalize = experiments::ParseSbatchJobId(
        RunAndCapture({sbatch.string(), "--parsable", "--dependency=afterany:" + array,
                       (slurm_dir / "finalize.sbatch").string()}));
    std::printf("%s\n%s\n", array.c_str(), finalize.c_str());
    std::fprintf(stderr, "vigil slurm: submitted array job %s (%d tasks) and finalize job %s; logs in %s\n",
                 array.c_str(), job.tasks, finalize.c_str(), slurm_dir.c_str());
    return 0;
  });
}

}  // namespace vigil::app
