// `vigil simulate`: writes a simulated dataset directory (docs/formats.md) from a run configuration.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "core/output.h"
#include "experiments/runs/run_config.h"
#include "sim/simulator.h"

namespace vigil::app {

void AddSimulateCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand("simulate",
                                  "simulate IMU, ground truth, glitches and feature tracks into a dataset "
                                  "directory (--images: also rendered camera images in the EuRoC layout "
                                  "mav0/ and scene.obj)");
  struct Args {
    ConfigArgs config;
    std::string output;
    bool force = false, images = false;
  };
  auto args = std::make_shared<Args>();
  args->config.AddTo(cmd);
  cmd->add_option("-o,--output", args->output, "dataset directory to write")->required();
  cmd->add_flag(
      "--images", args->images,
      "render camera images (same as --set images.enabled=true): mav0/ (EuRoC layout) and scene.obj");
  cmd->add_flag("--force", args->force,
                "replace an output directory vigil wrote (files it did not write are kept)");
  SetAction(cmd, [args] {
    std::vector<std::string> overrides = args->config.AllOverrides();
    if (args->images) overrides.emplace_back("images.enabled=true");
    experiments::RunConfig config = experiments::LoadRunConfig(args->config.config_path, overrides);
    std::vector<std::filesystem::path> inputs = experiments::RunConfigInputs(config);
    inputs.emplace_back(args->config.config_path);
    RefuseOutputOverInputs(args->output, inputs);
    const auto start = std::chrono::steady_clock::now();
    Dataset d;
    try {
      d = sim::SimulateToDirectory(config.sim, config.seed, config::ToYaml(config), args->output,
                                   args->force);
    } catch (const InputError& e) {
      experiments::RethrowLocated(args->config.config_path, overrides, e);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::size_t fewest = d.frames.empty() ? 0 : d.frames.front().features.size(), observations = 0;
    for (const CameraFrame& f : d.frames) {
      fewest = std::min(fewest, f.features.size());
      observations += f.features.size();
    }
    std::fprintf(
        stderr,
        "vigil simulate: %zu IMU samples, %zu glitch offsets, %zu landmarks, %zu camera frames "
        "(features per frame: min %zu, mean %.1f) -> %s (%.3f s)\n",
        d.imu.size(), d.glitches.size(), d.landmarks.size(), d.frames.size(), fewest,
        d.frames.empty() ? 0.0 : static_cast<double>(observations) / static_cast<double>(d.frames.size()),
        args->output.c_str(), seconds);
    if (config.sim.images.enabled)
      std::fprintf(stderr, "vigil simulate: %zu images %d x %d in %s/mav0/cam0/data, scene.obj\n",
                   d.frames.size(), config.sim.camera.width, config.sim.camera.height, args->output.c_str());
    return 0;
  });
}

}  // namespace vigil::app
