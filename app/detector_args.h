// Command-line pieces shared by `vigil templates` and `vigil clean`: where the IMU data is, and the detector
// options (defaults + `--set detector.key=value`).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "detectors/detector_options.h"

namespace vigil::app {

// `--set detector.x.y=value` overrides, applied in order to the default detector options.
struct DetectorArgs {
  std::vector<std::string> overrides;

  void AddTo(CLI::App* cmd);
  // InputError naming the override on an unknown key or a bad value.
  detectors::DetectorOptions Resolve() const;
};

// The detector options under their config key ("detector:"), e.g. for a config.yaml beside results.
std::string DetectorConfigYaml(const detectors::DetectorOptions& options);

// DATASET of `vigil templates` / `vigil clean`: a dataset directory (vigil's, or a EuRoC folder) or the
// path of an EuRoC imu0 CSV file.
struct ImuInput {
  std::filesystem::path imu;  // the CSV to read
  std::filesystem::path dir;  // where imu_clean.csv and glitches.csv may sit beside it
};
// For a directory: `file_in_dir` inside it, else a EuRoC folder's mav0/imu0/data.csv (InputError if neither).
// For a file: the file itself.
ImuInput ResolveImuInput(const std::string& dataset, const std::string& file_in_dir);

}  // namespace vigil::app
