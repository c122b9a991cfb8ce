// The evaluation command's options and action, shared by `vigil eval` (cmd_eval.cc) and the standalone
// `vigil-eval` (eval_main.cc). It needs only the evaluation library and core/, so `vigil-eval` links nothing
// else (no OpenCV, oneTBB, Ceres or OSMesa); tests/app/eval_binary_test.cc checks this.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace vigil::app {

struct EvalArgs {
  std::string gt, est, align = "posyaw";
  std::vector<double> distances;
  bool json = false;
};

// The one-line description of the command (its help text).
extern const char* const kEvalDescription;

// Adds GT, EST, --align, --distances and --json to `cmd`, parsed into `*args`.
void AddEvalOptions(CLI::App* cmd, EvalArgs* args);

// Evaluates args.est against args.gt and prints the table (or JSON) to stdout; returns the exit status.
// InputError for bad input (an unknown alignment, a length <= 0, an unreadable file, no matched pose).
int RunEval(const EvalArgs& args);

}  // namespace vigil::app
