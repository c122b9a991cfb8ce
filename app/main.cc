// vigil: visual-inertial odometry under IMU faults. See README.md and docs/cli.md.
#include <cstdint>
#include <map>
#include <optional>

#include "app/cli_main.h"
#include "app/commands.h"
#include "app/set_args.h"
#include "app/solver_logging.h"
#include "core/config.h"
#include "core/error.h"
#include "experiments/external/child_process.h"

namespace vigil::app {
namespace {
std::map<const CLI::App*, Action>& Actions() {
  static std::map<const CLI::App*, Action> actions;
  return actions;
}

}  // namespace

void SetAction(CLI::App* cmd, Action action) { Actions()[cmd] = std::move(action); }

void ConfigArgs::AddTo(CLI::App* cmd, bool optional) {
  auto* opt = cmd->add_option("CONFIG", config_path, "run configuration (YAML; see configs/README.md)");
  if (!optional) opt->required();
  AddSetOption(cmd, overrides, "override a config key: key.path=value (repeatable)");
  cmd->add_option("--seed", seed, "run seed 0 .. 2^63 - 1 (overrides the config's `seed`)");
}

std::vector<std::string> ConfigArgs::AllOverrides() const {
  std::vector<std::string> all = overrides;
  if (!seed.empty()) all.push_back("seed=" + std::to_string(config::ParseSeedArgument(seed)));
  return all;
}

}  // namespace vigil::app

int main(int argc, char** argv) {
  using namespace vigil::app;
  InitSolverLogging(argc > 0 ? argv[0] : "vigil");
  CLI::App root{"vigil: a laboratory for visual-inertial odometry under IMU faults"};
  root.require_subcommand(1);
  root.set_version_flag("--version", "vigil 0.1.0");
  AddConfigCommand(root);
  AddSimulateCommand(root);
  AddTemplatesCommand(root);
  AddCleanCommand(root);
  AddInjectCommand(root);
  AddImportCommand(root);
  AddTrackCommand(root);
  AddRunCommand(root);
  AddEstimateCommand(root);
  AddEvalCommand(root);
  AddPlotCommand(root);
  AddSweepCommand(root);
  AddPaperCommand(root);
  AddMapCommand(root);
  AddRocCommand(root);
  AddTablesCommand(root);
  AddRegressCommand(root);
  AddSlurmCommand(root);
  if (const std::optional<int> status = ParseCommandLine(root, argc, argv)) return *status;
  for (const CLI::App* cmd : root.get_subcommands()) {
    // Nested subcommands (`vigil plot run`): the action sits on the innermost parsed one.
    while (!cmd->get_subcommands().empty()) cmd = cmd->get_subcommands().front();
    auto it = Actions().find(cmd);
    if (it == Actions().end()) continue;
    try {
      return RunReportingErrors(it->second);
    } catch (const vigil::experiments::Interrupted& interrupted) {
      // An external program was running: it and everything it started are gone, the temporary files too.
      vigil::experiments::EndWithSignal(interrupted.signal);
    }
  }
  return 0;
}
