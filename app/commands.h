// The subcommands of `vigil`. Each Add*Command registers one subcommand (its options and its action) on the
// root app; the actions throw vigil::InputError for bad input (exit 2) and return the exit status otherwise.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace vigil::app {

// The action of a subcommand, run after parsing; returns the exit status.
using Action = std::function<int()>;

// Registers `action` to run when `cmd` is the parsed subcommand.
void SetAction(CLI::App* cmd, Action action);

// Options that several commands share: a config file, --set overrides and --seed.
struct ConfigArgs {
  std::string config_path;
  std::vector<std::string> overrides;
  std::string seed;  // empty: keep the config's seed

  // Adds CONFIG (positional, required unless `optional`), --set and --seed to `cmd`.
  void AddTo(CLI::App* cmd, bool optional = false);
  // The overrides with --seed appended as "seed=N"; InputError unless --seed is an integer 0 .. 2^63 - 1.
  std::vector<std::string> AllOverrides() const;
};

void AddConfigCommand(CLI::App& root);
void AddSimulateCommand(CLI::App& root);
void AddTemplatesCommand(CLI::App& root);
void AddCleanCommand(CLI::App& root);
void AddInjectCommand(CLI::App& root);
void AddImportCommand(CLI::App& root);
void AddTrackCommand(CLI::App& root);
void AddPlotCommand(CLI::App& root);
void AddEvalCommand(CLI::App& root);
void AddRunCommand(CLI::App& root);
void AddEstimateCommand(CLI::App& root);
void AddSweepCommand(CLI::App& root);
void AddTablesCommand(CLI::App& root);
void AddPaperCommand(CLI::App& root);
void AddMapCommand(CLI::App& root);
void AddRocCommand(CLI::App& root);
void AddRegressCommand(CLI::App& root);
void AddSlurmCommand(CLI::App& root);

}  // namespace vigil::app
