// vigil-eval: `vigil eval` as an executable of its own, linking only the evaluation library and core/
// (app/eval_command.h). Same arguments, output, messages and exit statuses as `vigil eval`.
#include <optional>

#include "app/cli_main.h"
#include "app/eval_command.h"

int main(int argc, char** argv) {
  using namespace vigil::app;
  CLI::App app{kEvalDescription, "vigil-eval"};
  app.set_version_flag("--version", "vigil-eval 0.1.0");
  EvalArgs args;
  AddEvalOptions(&app, &args);
  if (const std::optional<int> status = ParseCommandLine(app, argc, argv)) return *status;
  return RunReportingErrors([&args] { return RunEval(args); });
}
