// The configuration of one run: simulation, detection, estimation and evaluation.
//
// This is the schema of configs/*.yaml and of the config.yaml written into every dataset and run directory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/config_section.h"
#include "detectors/detector_options.h"
#include "estimator/estimator_options.h"
#include "evaluation/evaluation_options.h"
#include "experiments/external/external_estimator_options.h"
#include "frontend/frontend_options.h"
#include "sim/sim_options.h"

namespace vigil::experiments {

// The run config's sections that `vigil clean`, `vigil templates` and `vigil track` also take on their own
// (their `--set` keys and the config.yaml they write): one key and description each, so that those files
// merge into a run's config.
struct SectionName {
  const char* key;
  const char* description;
};
inline constexpr SectionName kFrontendSection{"frontend",
                                              "visual front-end: feature tracks from camera images"};
inline constexpr SectionName kDetectorSection{"detector", "glitch detection and mitigation"};
inline config::ConfigSection<frontend::FrontendOptions> FrontendSection() {
  return {kFrontendSection.key, kFrontendSection.description};
}
inline config::ConfigSection<detectors::DetectorOptions> DetectorSection() {
  return {kDetectorSection.key, kDetectorSection.description};
}

struct RunConfig {
  uint64_t seed = 1;
  sim::SimOptions sim;
  frontend::FrontendOptions frontend;
  detectors::DetectorOptions detector;
  RunEstimatorOptions estimator;  // vigil's estimator's options, and which estimator runs
  evaluation::EvaluationOptions evaluation;

  template <class V>
  void Visit(V& v) {
    v.Field("seed", seed, "run seed: every random stream derives from (seed, purpose)");
    sim.Visit(v);  // the simulator's sections sit at the top level
    v.Section(kFrontendSection.key, frontend, kFrontendSection.description);
    v.Section(kDetectorSection.key, detector, kDetectorSection.description);
    v.Section("estimator", estimator, "sliding-window visual-inertial estimator");
    v.Section("evaluation", evaluation, "trajectory evaluation");
  }
};

// Loads `path` (when not empty), then applies `overrides` ("key.path=value", in order), then checks
// cross-field constraints. Throws InputError naming the file, line and key.
RunConfig LoadRunConfig(const std::string& path, const std::vector<std::string>& overrides = {});

// Makes every input path of `config` usable from anywhere, as core/data_dir.h ResolveInputPath does against
// `base_dir` (the config file's directory, or the working directory for --set values): the simulator's files
// (sim::ResolveRelativePaths), detector.dtw.templates_file and detector.calibration_dataset.
void ResolveRelativePaths(const std::filesystem::path& base_dir, RunConfig* config);

// Cross-field checks that a single key's bounds cannot express; throws InputError("<origin>: key: reason").
void ValidateRunConfig(const RunConfig& config, const std::string& origin);

// The keys a ValidateRunConfig message "<origin>: key: reason" is about, to find where their values came
// from: the key at fault first, then the dotted keys its reason names (a cross-key check such as
// "imu.rate_hz: must be at least camera.rate_hz"). Empty when `message` does not start with "<origin>: ";
// else `rest` gets "key: reason".
std::vector<std::string> KeysOfConfigError(const std::string& message, const std::string& origin,
                                           std::string* rest);

// A problem "key: reason" with the configuration loaded from `path` (empty: none) and `overrides`, located
// where the value at fault came from: "--set key=value: reason" for the last --set of a key it is about,
// else "path:line: key: reason" for such a key's line in the file, else "path: key: reason" ("--set: ..."
// without a file).
InputError LocatedConfigError(const std::string& path, const std::vector<std::string>& overrides,
                              const std::string& problem);

// Whether `key` ("section.name") is a key of RunConfig.
bool IsRunConfigKey(const std::string& key);

// Rethrows `error` located as LocatedConfigError does when its message is "key: reason" for a RunConfig key
// (a value found wrong only once the run reads its inputs: duration_s beyond a recording's end, a spline too
// fine for it), else as it is.
[[noreturn]] void RethrowLocated(const std::string& path, const std::vector<std::string>& overrides,
                                 const InputError& error);

// The files a run with `config` reads besides its config file (waypoints, DTW templates, calibration
// dataset): what its output must not overwrite (core/output.h RefuseOutputOverInputs).
std::vector<std::filesystem::path> RunConfigInputs(const RunConfig& config);

// "key: PATH: no such file or directory" for the first input of RunConfigInputs that does not exist, with
// the key that names it; "" when every one exists.
std::string MissingInputProblem(const RunConfig& config);

}  // namespace vigil::experiments
