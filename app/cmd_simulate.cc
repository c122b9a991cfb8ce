// `vigil simulate`: writes a simulated dataset directory (formats.md) from a run configuration.
#include <chrono>
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "experiments/run_config.h"
#include "sim/simulator.h"

namespace vigil::app {

void AddSimulateCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand("simulate",
                                  "simulate IMU, ground truth, glitches and feature tracks into a dataset "
                                  "directory");
  struct Args {
    ConfigArgs config;
    std::string output;
    bool force = false;
  };
  auto args = std::make_shared<Args>();
  args->config.AddTo(cmd);
  cmd->add_option("-o,--output", args->output, "dataset directory to write")->required();
  cmd->add_flag("--force", args->force, "replace a non-empty output directory");
  SetAction(cmd, [args] {
    experiments::RunConfig config =
        experiments::LoadRunConfig(args->config.config_path, args->config.AllOverrides());
    const auto start = std::chrono::steady_clock::now();
    const Dataset d =
        sim::SimulateToDirectory(config.sim, config.seed, config::ToYaml(config), args->output, args->force);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(
        stderr,
        "vigil simulate: %zu IMU samples, %zu camera frames, %zu landmarks, %zu glitch offsets -> %s "
        "(%.3f s)\n",
        d.imu.size(), d.frames.size(), d.landmarks.size(), d.glitches.size(), args->output.c_str(), seconds);
    return 0;
  });
}

}  // namespace vigil::app
