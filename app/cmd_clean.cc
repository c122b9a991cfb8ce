// `vigil clean`: runs a detector + mitigation over an IMU CSV and writes the cleaned IMU, the per-sample
// flags and detection statistics (against glitches.csv / imu_clean.csv when they sit beside the input).
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/set_args.h"
#include "core/config.h"
#include "detectors/detector_options.h"
#include "experiments/commands/clean_command.h"

namespace vigil::app {

void AddCleanCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "clean",
      "run a glitch detector + mitigation on DATASET/imu.csv (or DATASET/mav0/imu0/data.csv, "
      "or an imu0 CSV path); writes DIR/imu.csv, DIR/detections.csv, DIR/detection.json, DIR/config.yaml");
  auto args = std::make_shared<experiments::CleanRequest>();
  experiments::CleanRequest& request = *args;
  cmd->add_option("DATASET", request.dataset, "dataset directory (vigil or EuRoC) or EuRoC imu0 CSV file")
      ->required();
  cmd->add_option("-o,--output", request.output,
                  "output directory (must not exist or be empty, unless --force)")
      ->required();
  cmd->add_option("--detector", request.detector,
                  "detector: " + config::EnumChoices(detectors::DetectorTypeNames()))
      ->required();
  cmd->add_option("--templates", request.templates,
                  "DTW template library (from `vigil templates`); required for dtw");
  AddSetOption(cmd, request.overrides, "override a detector key: detector.key.path=value (repeatable)");
  cmd->add_flag("--force", request.force,
                "replace an output directory vigil wrote (files it did not write are kept)");
  SetAction(cmd, [args] {
    const experiments::CleanResult result = experiments::CleanRecording(*args);
    std::fprintf(stderr, "vigil clean: %s\n", experiments::CleanSummary(result).c_str());
    return 0;
  });
}

}  // namespace vigil::app
