// `vigil estimate`: vigil's estimator (and front-end, when the recording has images but no features.csv)
// alone on a recording; writes a TUM trajectory and a status file. Also the command of an external-estimator
// run that uses vigil's own estimator (docs/external-estimators.md).
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "experiments/commands/estimate_command.h"

namespace vigil::app {

void AddEstimateCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand("estimate",
                                  "vigil's estimator alone on DATASET (a EuRoC folder or a vigil dataset; "
                                  "feature tracks from features.csv "
                                  "beside mav0/, else tracked from cam0 images); writes "
                                  "DIR/stamped_traj_estimate.txt and DIR/status.json");
  struct Args {
    std::string dataset, output, config;
    std::vector<std::string> overrides;
    std::string seed;
    bool force = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("DATASET", args->dataset, "recording: a EuRoC folder (mav0/) or a vigil dataset directory")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "output directory (must not exist or be empty, unless --force)")
      ->required();
  cmd->add_option(
      "--config", args->config,
      "run configuration: estimator options, gravity, seed, front-end (default: built-in defaults)");
  cmd->add_option("--set", args->overrides, "override a config key: key.path=value (repeatable)")->take_all();
  cmd->add_option("--seed", args->seed, "run seed (the ground-truth init perturbation derives from it)");
  cmd->add_flag("--force", args->force,
                "replace an output directory vigil wrote (files it did not write are kept)");
  SetAction(cmd, [args] {
    ConfigArgs config;
    config.overrides = args->overrides;
    config.seed = args->seed;
    const nlohmann::json status = experiments::EstimateToDirectory(
        args->dataset, args->config, config.AllOverrides(), args->output, args->force);
    const bool ok = status.at("status") == "ok";
    std::fprintf(stderr, "vigil estimate: %s, %lld poses%s%s -> %s\n", ok ? "ok" : "failed",
                 static_cast<long long>(status.at("output_poses").get<long long>()), ok ? "" : ": ",
                 ok ? "" : status.at("failure_reason").get<std::string>().c_str(), args->output.c_str());
    return ok ? 0 : 1;
  });
}

}  // namespace vigil::app
