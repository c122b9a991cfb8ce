// `vigil paper`: the paper's simulation experiment end to end (configs/paper_sweep.yaml: sweep + tables 2-4 +
// figures), then the estimator-noise ablation (configs/paper_noise_sweep.yaml into DIR/noise_ablation/) and
// reproduction.md (the paper's claims judged, experiments/reproduction.h).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/sweep_args.h"
#include "experiments/reproduction.h"
#include "plots/render.h"

namespace vigil::app {

void AddPaperCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "paper",
      "the paper's simulation experiment: glitch settings x {trunc, dtw, original} (the paper's methods) and "
      "vigil's variants x seeds, then tables 2-4, summary.md (with the published numbers beside ours), the "
      "estimator-noise ablation (DIR/noise_ablation/), reproduction.md (the paper's claims judged) and "
      "figures/*.png");
  struct Args {
    std::string sweep = std::string(VIGIL_CONFIG_DIR) + "/paper_sweep.yaml";
    std::string noise_sweep = std::string(VIGIL_CONFIG_DIR) + "/paper_noise_sweep.yaml";
    long long seeds = 10;
    SweepArgs run;
  };
  auto args = std::make_shared<Args>();
  args->run.AddTo(cmd);
  cmd->add_option("--seeds", args->seeds, "seeds per cell (1, 2, ... N)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--sweep", args->sweep, "the sweep file")->capture_default_str();
  cmd->add_option("--noise-sweep", args->noise_sweep,
                  "the estimator-noise ablation sweep (its own seeds, at most --seeds; empty: none)")
      ->capture_default_str();
  SetAction(cmd, [args] {
    experiments::SweepSpec spec = experiments::LoadSweepSpec(args->sweep);
    experiments::SetSeedCount(&spec, static_cast<uint64_t>(args->seeds));
    experiments::SweepSpec noise;
    if (!args->noise_sweep.empty()) {  // read (and checked) before anything runs
      noise = experiments::LoadSweepSpec(args->noise_sweep);
      experiments::SetSeedCount(&noise,
                                std::min<uint64_t>(noise.seeds.size(), static_cast<uint64_t>(args->seeds)));
    }
    int status = args->run.Run(spec, "paper");
    if (!args->noise_sweep.empty()) {
      SweepArgs ablation = args->run;
      ablation.output = (std::filesystem::path(args->run.output) / "noise_ablation").string();
      status = std::max(status, ablation.Run(noise, "paper (noise ablation)"));
      // reproduction.md again, now with the ablation beside the main sweep.
      const std::filesystem::path dir = args->run.output;
      experiments::WriteReproduction(dir, experiments::LoadSweepSpec((dir / "sweep.yaml").string()));
    }
    const auto figures = plots::RenderSweepFigures(args->run.output, plots::FigureOptions{});
    std::fprintf(stderr, "vigil paper: %zu figures -> %s\n", figures.size(),
                 (std::filesystem::path(args->run.output) / "figures").string().c_str());
    return status;
  });
}

}  // namespace vigil::app
