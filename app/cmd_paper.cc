// `vigil paper`: the paper's simulation experiment end to end (configs/paper_sweep.yaml: sweep + tables 2-4 +
// figures).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/config_dir.h"
#include "app/sweep_args.h"
#include "plots/render.h"

namespace vigil::app {

void AddPaperCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "paper",
      "the paper's simulation experiment: glitch settings x {trunc, dtw, original, hampel} x seeds, then "
      "tables 2-4, summary.md (with the published numbers beside ours) and figures/*.png");
  struct Args {
    std::string sweep;  // empty: the shipped configs/paper_sweep.yaml (app/config_dir.h)
    long long seeds = 10;
    SweepArgs run;
  };
  auto args = std::make_shared<Args>();
  args->run.AddTo(cmd);
  cmd->add_option("--seeds", args->seeds, "seeds per cell (1, 2, ... N)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--sweep", args->sweep,
                  "the sweep file (default: paper_sweep.yaml of the configs installed beside the binary, "
                  "<prefix>/share/vigil/configs, or of the source tree for the build tree's binary)");
  SetAction(cmd, [args] {
    const std::string sweep = args->sweep.empty() ? ShippedConfig("paper_sweep.yaml") : args->sweep;
    experiments::SweepSpec spec = experiments::LoadSweepSpec(sweep);
    experiments::SetSeedCount(&spec, static_cast<uint64_t>(args->seeds));
    const int status = args->run.Run(spec, "paper");
    // A shard's figures would show part of the sweep: `vigil tables DIR --figures` draws them at the end.
    if (args->run.list || !args->run.Shard().whole()) return status;
    const auto figures = plots::RenderSweepFigures(args->run.output, plots::FigureOptions{});
    std::fprintf(stderr, "vigil paper: %zu figures -> %s\n", figures.size(),
                 (std::filesystem::path(args->run.output) / "figures").string().c_str());
    return status;
  });
}

}  // namespace vigil::app
