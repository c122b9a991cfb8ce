#include "experiments/run_config.h"

#include <filesystem>

#include "core/error.h"
#include "detectors/detector.h"

namespace vigil::experiments {

RunConfig LoadRunConfig(const std::string& path, const std::vector<std::string>& overrides) {
  RunConfig config;
  if (!path.empty()) {
    config::LoadFile(path, config);
    sim::ResolveRelativePaths(std::filesystem::path(path).parent_path(),
                              &config.sim);  // relative to the file
  }
  for (const auto& o : overrides) config::ApplyOverride(o, config);
  sim::ResolveRelativePaths(std::filesystem::current_path(),
                            &config.sim);  // --set paths: relative to the cwd
  ValidateRunConfig(config, path.empty() ? "--set" : path);
  return config;
}

void ValidateRunConfig(const RunConfig& config, const std::string& origin) {
  sim::ValidateSimOptions(config.sim, origin);
  try {
    detectors::ValidateDetectorOptions(config.detector);
  } catch (const InputError& e) {
    throw InputError(origin + ": " + e.what());
  }
}

}  // namespace vigil::experiments
