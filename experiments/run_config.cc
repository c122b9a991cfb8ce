#include "experiments/run_config.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.h"
#include "detectors/detector.h"

namespace vigil::experiments {
namespace {

// Whether `text` names the dotted config key `key` as a whole word ("camera.rate_hz", not "rate_hz_max").
bool MentionsKey(const std::string& text, const std::string& key) {
  const auto word = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
  };
  for (std::size_t at = text.find(key); !key.empty() && at != std::string::npos; at = text.find(key, at + 1))
    if ((at == 0 || !word(text[at - 1])) && (at + key.size() == text.size() || !word(text[at + key.size()])))
      return true;
  return false;
}

}  // namespace

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
  const std::string origin = path.empty() ? "--set" : path;
  try {
    ValidateRunConfig(config, origin);
  } catch (const InputError& e) {
    // "origin: key: reason": name the --set that gave the key its value, else the --set of a key the reason
    // names (a cross-key check such as "imu.rate_hz: must be at least camera.rate_hz"), else the key's line.
    const std::string message = e.what(), prefix = origin + ": ";
    if (message.compare(0, prefix.size(), prefix) != 0) throw;
    const std::string rest = message.substr(prefix.size());
    const std::string key = rest.substr(0, rest.find(": "));
    const std::string reason = rest.substr(std::min(rest.size(), key.size() + 2));
    const auto set_of = [&](const std::string& k) -> const std::string* {
      for (auto o = overrides.rbegin(); o != overrides.rend(); ++o)  // the last --set of a key wins
        if (o->compare(0, k.size() + 1, k + "=") == 0) return &*o;
      return nullptr;
    };
    if (const std::string* o = set_of(key)) throw InputError("--set " + *o + ": " + rest);
    for (const auto& o : overrides) {
      const std::string other = o.substr(0, o.find('='));
      if (MentionsKey(reason, other)) throw InputError("--set " + *set_of(other) + ": " + rest);
    }
    if (path.empty()) throw;
    const int line = config::KeyLine(config::LoadYamlFile(path), key);
    if (line > 0) throw InputError(Located(path, line, rest));
    throw;
  }
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

std::vector<std::filesystem::path> RunConfigInputs(const RunConfig& config) {
  std::vector<std::filesystem::path> inputs;
  for (const std::string& file : {config.sim.trajectory.waypoints_file, config.detector.dtw.templates_file})
    if (!file.empty()) inputs.emplace_back(file);
  return inputs;
}

}  // namespace vigil::experiments
