// `vigil templates`: builds a DTW template library (and calibrates the detection threshold) from clean IMU
// data.
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/set_args.h"
#include "experiments/commands/templates_command.h"

namespace vigil::app {

void AddTemplatesCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "templates",
      "build a DTW template library from clean IMU data: DATASET/imu_clean.csv (else DATASET/imu.csv) or an "
      "imu0 CSV path. Use data from another recording (another seed) than the one it will clean.");
  auto args = std::make_shared<experiments::TemplatesRequest>();
  cmd->add_option("DATASET", args->dataset, "dataset directory or EuRoC imu0 CSV file")->required();
  cmd->add_option("-o,--output", args->output, "template library to write (YAML)")->required();
  AddSetOption(cmd, args->overrides, "override a detector key: detector.key.path=value (repeatable)");
  cmd->add_flag("--force", args->force, "replace a template library vigil wrote");
  SetAction(cmd, [args] {
    args->report = [](const std::string& lines) { std::fputs(lines.c_str(), stderr); };
    experiments::BuildTemplateLibraryFile(*args);
    return 0;
  });
}

}  // namespace vigil::app
