// Options shared by `vigil sweep` and `vigil paper`: the output directory, threads, resume/force, quiet.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "experiments/sweep_spec.h"

namespace vigil::app {

struct SweepArgs {
  std::string output;
  int threads = 0;
  bool resume = false, force = false, quiet = false;

  void AddTo(CLI::App* cmd);
  // Runs `spec` into `output` with the real run (ExecuteRun), writes the tables, reports on stderr.
  // Returns the exit status (0; failed runs are results, counted in summary.md).
  int Run(const experiments::SweepSpec& spec, const char* command) const;
};

}  // namespace vigil::app
