#include "experiments/commands/run_command.h"

#include "core/error.h"
#include "core/output.h"
#include "core/recording_files.h"
#include "experiments/runs/external_estimator.h"

namespace vigil::experiments {

nlohmann::json RunToDirectory(const std::string& config_path, const std::vector<std::string>& overrides,
                              const RunOptions& options, const std::filesystem::path& dir, bool force) {
  const RunConfig config = LoadRunConfig(config_path, overrides);
  // A simulated run has feature tracks and no camera images on disk (as a sweep's runs): an external
  // estimator that needs images is refused here, at the line or --set that asked for them.
  if (options.dataset_dir.empty())
    if (const std::string why = ExternalInputProblem(config, false, true); !why.empty())
      throw LocatedConfigError(config_path, overrides, why);
  std::vector<std::filesystem::path> inputs = RunConfigInputs(config);
  inputs.emplace_back(config_path);
  for (const std::filesystem::path& input : RecordingInputPaths(options.dataset_dir)) inputs.push_back(input);
  RefuseOutputOverInputs(dir, inputs);
  StagedDirectory out(dir, force);
  nlohmann::json metrics;
  try {
    metrics = ExecuteRun(config, options, out.path());
  } catch (const InputError& e) {
    RethrowLocated(config_path, overrides, e);
  }
  out.Commit();
  return metrics;
}

}  // namespace vigil::experiments
