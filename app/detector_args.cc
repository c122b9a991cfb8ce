#include "app/detector_args.h"

#include "core/config.h"
#include "core/error.h"

namespace vigil::app {
namespace {

// The detector options as they sit in a run config, so that `--set detector.dtw.dims=3` reads the same here.
struct DetectorConfig {
  detectors::DetectorOptions detector;

  template <class V>
  void Visit(V& v) {
    v.Section("detector", detector, "glitch detection and mitigation");
  }
};

}  // namespace

void DetectorArgs::AddTo(CLI::App* cmd) {
  cmd->add_option("--set", overrides, "override a detector key: detector.key.path=value (repeatable)")
      ->take_all();
}

detectors::DetectorOptions DetectorArgs::Resolve() const {
  DetectorConfig config;
  for (const std::string& assignment : overrides) config::ApplyOverride(assignment, config);
  return config.detector;
}

std::string DetectorConfigYaml(const detectors::DetectorOptions& options) {
  DetectorConfig config{options};
  return config::ToYaml(config);
}

ImuInput ResolveImuInput(const std::string& dataset, const std::string& file_in_dir) {
  namespace fs = std::filesystem;
  const fs::path path(dataset);
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    const fs::path file = path / file_in_dir;
    if (!fs::exists(file, ec)) throw InputError(file.string() + ": not found (expected a dataset directory)");
    return {file, path};
  }
  if (!fs::exists(path, ec)) throw InputError(dataset + ": no such file or directory");
  return {path, path.parent_path().empty() ? fs::path(".") : path.parent_path()};
}

}  // namespace vigil::app
