// `vigil import`: a ROS 1 bag into the EuRoC layout vigil reads (core/bag/bag_import.h).
#include <unistd.h>

#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "core/bag/bag_import.h"
#include "core/bag/bag_presets.h"

namespace vigil::app {
namespace {

struct ImportArgs {
  bag::BagImportRequest request;
  bool quiet = false;
};

// "vigil import: 1200/58000 messages (2 %)", redrawn in place on a terminal at each whole percent; silent
// when stderr is not a terminal, or with --quiet (as a sweep's progress bar).
bag::ImportProgress TerminalProgress(bool quiet) {
  if (quiet || isatty(fileno(stderr)) == 0) return {};
  auto last_percent = std::make_shared<int>(-1);
  return [last_percent](std::size_t done, std::size_t total) {
    const int percent = total == 0 ? 100 : static_cast<int>(100 * done / total);
    if (percent == *last_percent && done != total) return;
    *last_percent = percent;
    std::fprintf(stderr, "\rvigil import: %zu/%zu messages (%d %%)%s", done, total, percent,
                 done == total ? "\n" : "");
  };
}

}  // namespace

void AddImportCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "import",
      "convert a ROS 1 bag into the EuRoC layout vigil reads: sensor_msgs/Imu -> mav0/imu0, "
      "sensor_msgs/Image "
      "-> mav0/cam0 (8-bit grayscale PNG), a pose topic -> mav0/state_groundtruth_estimate0, the sensors' "
      "sensor.yaml and import.yaml");
  auto args = std::make_shared<ImportArgs>();
  bag::BagImportRequest& r = args->request;
  cmd->add_option("BAG", r.bag, "the ROS 1 bag (format 2.0)")->required();
  cmd->add_option("-o,--output", r.output, "directory to write (must not exist or be empty, unless --force)")
      ->required();
  cmd->add_option("--preset", r.preset,
                  "the dataset whose topic names and calibrations are the defaults: " + bag::BagPresetNames())
      ->capture_default_str();
  cmd->add_option("--imu-topic", r.imu_topic, "sensor_msgs/Imu topic (default: the preset's, /imu0)");
  cmd->add_option("--image-topic", r.image_topic,
                  "sensor_msgs/Image topic (default: the preset's, /cam0/image_raw); none: no images");
  cmd->add_option("--groundtruth-topic", r.groundtruth_topic,
                  "geometry_msgs/PoseStamped, TransformStamped or nav_msgs/Odometry topic (default: the "
                  "preset's, when the bag has it); none: no ground truth");
  cmd->add_option("--imu-yaml", r.imu_yaml,
                  "an imu0 sensor.yaml (EuRoC layout) to copy (default: the preset's IMU noise model)");
  cmd->add_option("--camera-yaml", r.camera_yaml,
                  "a cam0 sensor.yaml (EuRoC layout, pinhole) to copy (default: the preset's calibration)");
  cmd->add_flag("--force", r.force,
                "replace an output directory vigil wrote (files it did not write are kept)");
  cmd->add_flag("-q,--quiet", args->quiet, "no progress on a terminal");
  SetAction(cmd, [args] {
    const bag::BagImportResult result = bag::ImportBag(args->request, TerminalProgress(args->quiet));
    std::fprintf(stderr, "vigil import: %s\n", bag::BagImportSummary(args->request, result).c_str());
    return 0;
  });
}

}  // namespace vigil::app
