// `vigil run`: one run (simulate or read a dataset, detect + mitigate, estimate, evaluate) into a run
// directory.
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "experiments/commands/run_command.h"
#include "experiments/runs/run_metrics.h"

namespace vigil::app {

void AddRunCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "run",
      "one run: simulate (or --dataset), detect + mitigate glitches, estimate, evaluate; "
      "writes a run directory (config.yaml, metrics.json, stamped_*.txt, landmarks.csv, imu_axis.csv, "
      "and detections.csv when a detector ran)");
  struct Args {
    ConfigArgs config;
    std::string output, dataset;
    bool force = false, no_trajectories = false, no_figure_data = false;
  };
  auto args = std::make_shared<Args>();
  args->config.AddTo(cmd);
  cmd->add_option("-o,--output", args->output,
                  "run directory to write (must not exist or be empty, unless --force)")
      ->required();
  cmd->add_option("--dataset", args->dataset,
                  "read this dataset directory (vigil simulate) instead of simulating");
  cmd->add_flag("--force", args->force,
                "replace an output directory vigil wrote (files it did not write are kept)");
  cmd->add_flag("--no-trajectories", args->no_trajectories, "no stamped_*.txt and no detections.csv");
  cmd->add_flag("--no-figure-data", args->no_figure_data,
                "no landmarks.csv and no imu_axis.csv (what the run's figures 1, 2 and 5 draw)");
  SetAction(cmd, [args] {
    experiments::RunOptions options;
    options.dataset_dir = args->dataset;
    options.write_trajectories = !args->no_trajectories;
    options.write_figure_data = !args->no_figure_data;
    const nlohmann::json metrics = experiments::RunToDirectory(
        args->config.config_path, args->config.AllOverrides(), options, args->output, args->force);
    std::fprintf(stderr, "vigil run: %s -> %s\n", experiments::RunSummaryLine(metrics).c_str(),
                 args->output.c_str());
    return metrics.at("status") == "ok" ? 0 : 1;
  });
}

}  // namespace vigil::app
