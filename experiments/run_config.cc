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
  if (path.empty()) {
    ValidateRunConfig(config, "--set");
    return config;
  }
  try {
    ValidateRunConfig(config, path);
  } catch (const InputError& e) {
    // "path: key: reason": name the line of the key, or the --set that gave it its value.
    const std::string message = e.what(), prefix = path + ": ";
    if (message.compare(0, prefix.size(), prefix) != 0) throw;
    const std::string rest = message.substr(prefix.size());
    const std::string key = rest.substr(0, rest.find(": "));
    for (const auto& o : overrides)
      if (o.compare(0, key.size() + 1, key + "=") == 0) throw InputError("--set " + rest);
    const int line = config::KeyLine(config::LoadYamlFile(path), key);
    if (line > 0) throw InputError(Located(path, line, rest));
    throw;
  }
  return config;
}

void ValidateRunConfig(const RunConfig& config, const std::string& origin) {
  sim::ValidateSimOptions(config.sim, origin);
  if (const std::string why = frontend::ValidateEvaluationOptions(config.frontend.evaluation); !why.empty())
    throw InputError(origin + ": frontend.evaluation." + why);
  try {
    detectors::ValidateDetectorOptions(config.detector);
  } catch (const InputError& e) {
    throw InputError(origin + ": " + e.what());
  }
}

std::vector<std::filesystem::path> RunConfigInputs(const RunConfig& config) {
  std::vector<std::filesystem::path> inputs;
  for (const std::string& file : {config.sim.trajectory.waypoints_file, config.detector.dtw.templates_file})
    if (!file.empty()) inputs.emplace_back(file);
  return inputs;
}

}  // namespace vigil::experiments
