// A sweep in a process of its own, for the tests that need one: killed with SIGKILL in the middle
// (SweepRunner.ResumeAfterKillGivesTheSameResults) or run as two concurrent shards of one directory
// (SweepRunner.ConcurrentShardsGiveTheSameResultsAsOneSweep). The runs are fakes (FakeMetrics) that last
// SLEEP_MS each.
//
//   sweep_helper SWEEP OUT SLEEP_MS [SHARD [READY_PREFIX PARTIES]]
//
// SHARD is "I/N" ("-": the whole sweep). With READY_PREFIX, the process creates READY_PREFIX<pid> and waits
// (at most 20 s, else exit 3) until PARTIES such files exist, so that every party is running before any
// starts its sweep. Exit 0 when done, 2 on bad input, 1 on any other error.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "core/error.h"
#include "experiments/sweep_runner.h"
#include "tests/experiments/sweep_test_util.h"

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

}  // namespace

int main(int argc, char** argv) {
  using namespace vigil::experiments;
  if (argc != 4 && argc != 5 && argc != 7) {
    std::fprintf(stderr, "usage: sweep_helper SWEEP OUT SLEEP_MS [SHARD [READY_PREFIX PARTIES]]\n");
    return 2;
  }
  try {
    SweepRunOptions options;
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
