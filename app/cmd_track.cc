// `vigil track`: the visual front-end alone: a dataset's camera images -> feature tracks (features.csv), with
// the tracker's statistics and, for a rendered dataset, their errors against the scene (frontend.json).
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/set_args.h"
#include "experiments/commands/track_command.h"

namespace vigil::app {

void AddTrackCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "track",
      "run the visual front-end (KLT tracker) on DATASET's camera images (EuRoC cam0 layout: a EuRoC folder "
      "or a dataset of `vigil simulate --images`); writes DIR/features.csv, DIR/frontend.json and "
      "DIR/config.yaml");
  auto args = std::make_shared<experiments::TrackRequest>();
  cmd->add_option("DATASET", args->dataset, "dataset directory with mav0/cam0 (EuRoC layout)")->required();
  cmd->add_option("-o,--output", args->output,
                  "output directory (must not exist or be empty, unless --force)")
      ->required();
  AddSetOption(cmd, args->overrides, "override a front-end key: frontend.key=value (repeatable)");
  cmd->add_flag("--force", args->force,
                "replace an output directory vigil wrote (files it did not write are kept)");
  SetAction(cmd, [args] {
    const experiments::TrackResult result = experiments::TrackToDirectory(*args);
    std::fprintf(stderr, "vigil track: %s\n", experiments::TrackSummary(*args, result).c_str());
    return 0;
  });
}

}  // namespace vigil::app
