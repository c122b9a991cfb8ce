// `vigil sweep`: a Monte Carlo grid (axes x methods x seeds) from a sweep file, parallel and resumable.
#include <memory>

#include "app/commands.h"
#include "app/sweep_args.h"

namespace vigil::app {

void AddSweepCommand(CLI::App& root) {
  auto* cmd =
      root.add_subcommand("sweep",
                          "run a Monte Carlo sweep (see experiments/sweeps/sweep_spec.h for the file) into a "
                          "directory: runs/<id>/, results.csv, tables 2-4, summary.md");
  struct Args {
    std::string sweep;
    SweepArgs run;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("SWEEP", args->sweep, "sweep file (YAML), e.g. configs/paper_sweep.yaml")->required();
  args->run.AddTo(cmd);
  SetAction(cmd, [args] { return args->run.Run(experiments::LoadSweepSpec(args->sweep), "sweep"); });
}

}  // namespace vigil::app
