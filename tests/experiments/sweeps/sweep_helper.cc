// A sweep in a process of its own, for the tests that need one: killed with SIGKILL in the middle
// (SweepRunner.ResumeAfterKillGivesTheSameResults) or run as two concurrent shards of one directory
// (SweepRunner.ConcurrentShardsGiveTheSameResultsAsOneSweep). The runs are fakes (FakeMetrics).
//
//   sweep_helper SWEEP OUT SLEEP_MS [SHARD [READY_PREFIX PARTIES]]
//   sweep_helper SWEEP OUT --die-at-run N
//
// First form: each run lasts SLEEP_MS. SHARD is "I/N" ("-": the whole sweep). With READY_PREFIX, the process
// creates READY_PREFIX<pid> and waits (at most 20 s, else exit 3) until PARTIES such files exist, so that
// every party is running before any starts its sweep. Second form: the sweep runs on one thread, and the
// process kills itself with SIGKILL inside its run N (counted from 0, in plan order) after that run has
// written its config.yaml: exactly N runs are committed and run N is left half-written in its staging
// directory. Exit 0 when done, 2 on bad input, 1 on any other error.
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>

#include "core/error.h"
#include "experiments/sweeps/sweep_runner.h"
#include "tests/experiments/sweeps/sweep_test_util.h"

namespace {
namespace fs = std::filesystem;

// The parties that have announced themselves: files named <prefix><pid> beside the prefix.
int Announced(const fs::path& prefix) {
  int n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(prefix.parent_path(), ec))
    if (e.path().filename().string().rfind(prefix.filename().string(), 0) == 0) ++n;
  return n;
}

bool Rendezvous(const fs::path& prefix, int parties) {
  std::ofstream(prefix.string() + std::to_string(::getpid())) << "ready\n";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (Announced(prefix) < parties) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

// SlowFakeExecutor(0) that kills the process, without any clean-up, inside its run `die_at` (0-based).
vigil::experiments::RunExecutor DyingFakeExecutor(std::size_t die_at) {
  auto runs = std::make_shared<std::size_t>(0);  // one thread: no synchronisation needed
  const vigil::experiments::RunExecutor fake = vigil::experiments::testing::SlowFakeExecutor(0);
  return [runs, die_at, fake](const vigil::experiments::RunConfig& config,
                              const vigil::experiments::RunOptions& options, const fs::path& dir) {
    const nlohmann::json metrics = fake(config, options, dir);
    if ((*runs)++ == die_at) ::kill(::getpid(), SIGKILL);
    return metrics;
  };
}

}  // namespace

int main(int argc, char** argv) {
  using namespace vigil::experiments;
  const bool dying = argc == 5 && std::string(argv[3]) == "--die-at-run";
  if (argc != 4 && argc != 5 && argc != 7) {
    std::fprintf(stderr,
                 "usage: sweep_helper SWEEP OUT SLEEP_MS [SHARD [READY_PREFIX PARTIES]]\n"
                 "       sweep_helper SWEEP OUT --die-at-run N\n");
    return 2;
  }
  try {
    SweepRunOptions options;
    if (dying) {
      options.threads = 1;
      RunSweep(LoadSweepSpec(argv[1]), argv[2], options, DyingFakeExecutor(std::stoul(argv[4])));
      return 0;
    }
    options.threads = 2;
    if (argc >= 5 && std::string(argv[4]) != "-") {
      options.shard = ParseShard(argv[4]);
      options.threads = 1;
    }
    if (argc == 7 && !Rendezvous(argv[5], std::stoi(argv[6]))) {
      std::fprintf(stderr, "sweep_helper: the other parties did not start within 20 s\n");
      return 3;
    }
    RunSweep(LoadSweepSpec(argv[1]), argv[2], options,
             vigil::experiments::testing::SlowFakeExecutor(std::stoi(argv[3])));
    return 0;
  } catch (const vigil::InputError& e) {
    std::fprintf(stderr, "sweep_helper: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep_helper: error: %s\n", e.what());
    return 1;
  }
}
