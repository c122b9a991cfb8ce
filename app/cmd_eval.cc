// `vigil eval`: rpg-compatible ATE and relative errors of two TUM / rpg trajectory files (eval_command.h; the
// same command is the standalone `vigil-eval`).
#include <memory>

#include "app/commands.h"
#include "app/eval_command.h"

namespace vigil::app {

void AddEvalCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand("eval", kEvalDescription);
  auto args = std::make_shared<EvalArgs>();
  AddEvalOptions(cmd, args.get());
  SetAction(cmd, [args] { return RunEval(*args); });
}

}  // namespace vigil::app
