// Options shared by `vigil sweep` and `vigil paper`: the output directory, threads, resume/force, quiet, the
// shard and the plan listing.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "experiments/sweeps/sweep_shard.h"
#include "experiments/sweeps/sweep_spec.h"

namespace vigil::app {

// The most runs in parallel `-j` accepts (docs/safety.md): far above any machine's cores, far below what
// the thread pool can create.
inline constexpr int kMaxJobs = 256;

struct SweepArgs {
  std::string output;
  int threads = 0;
  bool resume = false, force = false, quiet = false, list = false;
  std::string shard;  // "I/N"; empty: the whole sweep

  void AddTo(CLI::App* cmd);
  // The parsed --shard (the whole sweep without it); InputError when malformed.
  experiments::SweepShard Shard() const;
  // With --list prints the plan's run ids (of the shard) on stdout; otherwise runs `spec` into `output` with
  // the real run (ExecuteRun), writes the tables (not for a shard), reports on stderr. Returns the exit
  // status (0; failed runs are results, counted in summary.md).
  int Run(const experiments::SweepSpec& spec, const char* command) const;
};

}  // namespace vigil::app
