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
  sim::ValidateSimOptions(config.sim, origin);
}

}  // namespace vigil::experiments
