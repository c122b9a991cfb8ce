#include "experiments/run_config.h"

namespace vigil::experiments {

RunConfig LoadRunConfig(const std::string& path, const std::vector<std::string>& overrides) {
  RunConfig config;
  if (!path.empty()) config::LoadFile(path, config);
  for (const auto& o : overrides) config::ApplyOverride(o, config);
  ValidateRunConfig(config, path.empty() ? "--set" : path);
  return config;
}

void ValidateRunConfig(const RunConfig& config, const std::string& origin) {
  const std::string camera = config.sim.camera.Validate();
  if (!camera.empty()) throw InputError(origin + ": camera." + camera);
  if (config.sim.glitch.enabled && config.sim.glitch.axes.empty())
    throw InputError(origin + ": glitch.axes: must name at least one axis when glitch.enabled is true");
  if (config.sim.imu.rate_hz < config.sim.camera.rate_hz)
    throw InputError(origin + ": imu.rate_hz: must be at least camera.rate_hz");
}

}  // namespace vigil::experiments
