#include "experiments/runs/run_config.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>
#include <utility>

#include "core/data_dir.h"
#include "core/error.h"
#include "core/recording_files.h"
#include "detectors/detector.h"
#include "experiments/external/external_command.h"
#include "sim/imu_presets.h"

namespace vigil::experiments {

namespace {

// The file and the overrides over the defaults, with `preset`'s figures as the defaults of imu.noise.*.
RunConfig LoadLayers(const std::string& path, const std::vector<std::string>& overrides,
                     sim::ImuPreset preset) {
  RunConfig config;
  sim::ApplyImuPreset(preset, &config.sim.imu);
  if (!path.empty()) {
    config::LoadFile(path, config);
    ResolveRelativePaths(std::filesystem::path(path).parent_path(), &config);  // relative to the file
  }
  for (const auto& o : overrides) config::ApplyOverride(o, config);
  ResolveRelativePaths(std::filesystem::current_path(), &config);  // --set paths: relative to the cwd
  return config;
}

}  // namespace

RunConfig LoadRunConfig(const std::string& path, const std::vector<std::string>& overrides) {
  RunConfig config = LoadLayers(path, overrides, sim::ImuPreset::kNone);
  // An IMU preset provides defaults: load again over its figures, so the keys the config writes still win.
  if (config.sim.imu.preset != sim::ImuPreset::kNone)
    config = LoadLayers(path, overrides, config.sim.imu.preset);
  try {
    sim::ResolveDurationToEnd(&config.sim);
  } catch (const InputError& e) {
    RethrowLocated(path, overrides, e);
  }
  const std::string origin = path.empty() ? "--set" : path;
  try {
    ValidateRunConfig(config, origin);
  } catch (const InputError& e) {
    std::string rest;
    if (KeysOfConfigError(e.what(), origin, &rest).empty()) throw;
    throw LocatedConfigError(path, overrides, rest);
  }
  return config;
}

void ResolveRelativePaths(const std::filesystem::path& base_dir, RunConfig* config) {
  sim::ResolveRelativePaths(base_dir, &config->sim);
  for (std::string* file : {&config->detector.dtw.templates_file, &config->detector.calibration_dataset})
    *file = ResolveInputPath(base_dir, *file);
}

void ValidateRunConfig(const RunConfig& config, const std::string& origin) {
  sim::ValidateSimOptions(config.sim, origin);
  for (const auto& [key, file] :
       {std::pair{"detector.dtw.templates_file", &config.detector.dtw.templates_file},
        std::pair{"detector.calibration_dataset", &config.detector.calibration_dataset}})
    if (const std::string why = UnsetDataDirReason(*file); !why.empty())
      throw InputError(origin + ": " + key + ": " + why);
  if (config.sim.imu.source == sim::ImuSource::kRecording &&
      config.frontend.features == frontend::FeatureSource::kTracked)
    throw InputError(origin +
                     ": frontend.features: tracked needs rendered images along a simulated trajectory, not "
                     "a semi-real dataset (imu.source recording)");
  if (const std::string why = frontend::ValidateEvaluationOptions(config.frontend.evaluation); !why.empty())
    throw InputError(origin + ": frontend.evaluation." + why);
  try {
    detectors::ValidateDetectorOptions(config.detector);
  } catch (const InputError& e) {
    throw InputError(origin + ": " + e.what());
  }
  if (config.estimator.backend == EstimatorBackend::kExternal)
    if (const std::string why = ValidateExternalOptions(config.estimator.external); !why.empty())
      throw InputError(origin + ": estimator.external." + why);
}

std::vector<std::string> KeysOfConfigError(const std::string& message, const std::string& origin,
                                           std::string* rest) {
  const std::string prefix = origin + ": ";
  if (message.compare(0, prefix.size(), prefix) != 0) return {};
  *rest = message.substr(prefix.size());
  const std::size_t colon = rest->find(": ");
  std::vector<std::string> keys{rest->substr(0, colon)};
  if (colon == std::string::npos) return keys;
  const auto in_key = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
  };
  const std::string reason = rest->substr(colon + 2);
  for (std::size_t i = 0; i < reason.size();) {
    std::size_t j = i;
    while (j < reason.size() && in_key(reason[j])) ++j;
    std::string word = reason.substr(i, j - i);
    while (!word.empty() && word.back() == '.') word.pop_back();  // the end of a sentence
    if (word.find('.') != std::string::npos && std::isalpha(static_cast<unsigned char>(word[0])))
      keys.push_back(word);
    i = std::max(j, i + 1);
  }
  return keys;
}

InputError LocatedConfigError(const std::string& path, const std::vector<std::string>& overrides,
                              const std::string& problem) {
  // Name where the value at fault came from: the last --set of a key the problem is about, else the line of
  // such a key in the file.
  const std::string origin = path.empty() ? "--set" : path;
  std::string rest;
  const std::vector<std::string> keys = KeysOfConfigError(origin + ": " + problem, origin, &rest);
  for (const std::string& key : keys)
    for (auto o = overrides.rbegin(); o != overrides.rend(); ++o)
      if (o->compare(0, key.size() + 1, key + "=") == 0) return InputError("--set " + *o + ": " + rest);
  if (!path.empty()) {
    const YAML::Node root = config::LoadYamlFile(path);
    for (const std::string& key : keys)
      if (const int line = config::KeyLine(root, key); line > 0) return InputError(Located(path, line, rest));
  }
  return InputError(origin + ": " + problem);
}

bool IsRunConfigKey(const std::string& key) {
  static const std::vector<config::KeyDoc> keys = [] {
    RunConfig defaults;
    return config::DescribeKeys(defaults);
  }();
  return std::any_of(keys.begin(), keys.end(), [&](const config::KeyDoc& k) { return k.path == key; });
}

void RethrowLocated(const std::string& path, const std::vector<std::string>& overrides,
                    const InputError& error) {
  const std::string message = error.what();
  if (!IsRunConfigKey(message.substr(0, message.find(": ")))) throw error;
  throw LocatedConfigError(path, overrides, message);
}

namespace {

// Each input file of a run and the key that names it.
std::vector<std::pair<const char*, const std::string*>> NamedInputs(const RunConfig& config) {
  return {{"trajectory.waypoints_file", &config.sim.trajectory.waypoints_file},
          {"trajectory.recording", &config.sim.trajectory.recording},
          {"detector.dtw.templates_file", &config.detector.dtw.templates_file},
          {"imu.recording", &config.sim.imu.recording},
          {"detector.calibration_dataset", &config.detector.calibration_dataset}};
}

}  // namespace

std::vector<std::filesystem::path> RunConfigInputs(const RunConfig& config) {
  std::vector<std::filesystem::path> inputs;
  // A recording stands for every entry of it (a linked image folder makes its target an input).
  for (const auto& [key, file] : NamedInputs(config))
    if (!file->empty())
      for (const std::filesystem::path& input : RecordingInputPaths(*file)) inputs.push_back(input);
  return inputs;
}

std::string MissingInputProblem(const RunConfig& config) {
  for (const auto& [key, file] : NamedInputs(config)) {
    std::error_code ec;
    if (!file->empty() && !std::filesystem::exists(*file, ec))
      return std::string(key) + ": " + *file + ": no such file or directory";
  }
  return "";
}

}  // namespace vigil::experiments
