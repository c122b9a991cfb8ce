// `vigil inject`: the simulator's IMU faults (glitch.*, faults.*) applied to a recording's IMU, written as a
// copy of the recording with labels (experiments/commands/inject_command.h).
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/set_args.h"
#include "experiments/commands/inject_command.h"

namespace vigil::app {

void AddInjectCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "inject",
      "apply the simulator's IMU faults (--set glitch.k=v, --set faults.k=v) to a recording's IMU: writes a "
      "copy of the recording (vigil dataset or EuRoC folder) with the faulty IMU, imu_clean.csv (the "
      "recording's own stream), glitches.csv and injection.yaml; images are linked, not copied");
  auto args = std::make_shared<experiments::InjectRequest>();
  cmd->add_option("DATASET", args->dataset,
                  "recording: a vigil dataset directory or a EuRoC folder (holding mav0/)")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "directory to write (must not exist or be empty, unless --force)")
      ->required();
  AddSetOption(cmd, args->overrides,
               "key.path=value (repeatable): glitch.*, faults.*, seed, gravity_mps2 with the simulator's "
               "meaning (configs/README.md)",
               /*take_all=*/false);
  cmd->add_option("--seed", args->seed, "seed of the fault draws (default 1)");
  cmd->add_flag("--force", args->force,
                "replace an output directory vigil wrote (files it did not write are kept)");
  SetAction(cmd, [args] {
    const experiments::InjectResult result = experiments::InjectRecording(*args);
    std::fprintf(stderr, "vigil inject: %s\n", experiments::InjectSummary(*args, result).c_str());
    return 0;
  });
}

}  // namespace vigil::app
