// `vigil paper`: the paper's simulation experiment end to end (configs/paper_sweep.yaml: sweep + tables 2-4 +
// figures), then the estimator-noise ablation (configs/paper_noise_sweep.yaml into DIR/noise_ablation/) and
// reproduction.md (the paper's claims judged, report/reproduction.h).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/config_dir.h"
#include "app/sweep_args.h"
#include "plots/render.h"
#include "report/reproduction.h"

namespace vigil::app {
namespace {

struct PaperArgs {
  std::string sweep;        // empty: the shipped configs/paper_sweep.yaml (app/config_dir.h)
  std::string noise_sweep;  // empty: the shipped configs/paper_noise_sweep.yaml
  bool no_noise_ablation = false;
  long long seeds = 10;
  SweepArgs run;
};

// The estimator-noise ablation into DIR/noise_ablation/, then reproduction.md again, now with the ablation
// beside the main sweep. Returns the ablation's exit status.
int RunNoiseAblation(const SweepArgs& run, const experiments::SweepSpec& noise) {
  SweepArgs ablation = run;
  ablation.output = (std::filesystem::path(run.output) / "noise_ablation").string();
  const int status = ablation.Run(noise, "paper (noise ablation)");
  const std::filesystem::path dir = run.output;
  report::WriteReproduction(dir, experiments::LoadSweepSpec((dir / "sweep.yaml").string()));
  return status;
}

}  // namespace

void AddPaperCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "paper",
      "the paper's simulation experiment: glitch settings x {trunc, dtw, original} (the paper's methods) and "
      "vigil's variants x seeds, then tables 2-4, summary.md (with the published numbers beside ours), the "
      "estimator-noise ablation (DIR/noise_ablation/), reproduction.md (the paper's claims judged) and "
      "figures/*.png");
  auto args = std::make_shared<PaperArgs>();
  args->run.AddTo(cmd);
  cmd->add_option("--seeds", args->seeds, "seeds per cell (1, 2, ... N)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--sweep", args->sweep,
                  "the sweep file (default: paper_sweep.yaml of the configs installed beside the binary, "
                  "<prefix>/share/vigil/configs, or of the source tree for the build tree's binary)");
  cmd->add_option("--noise-sweep", args->noise_sweep,
                  "the estimator-noise ablation sweep (its own seeds, at most --seeds; default: the shipped "
                  "paper_noise_sweep.yaml)");
  cmd->add_flag("--no-noise-ablation", args->no_noise_ablation, "skip the estimator-noise ablation");
  SetAction(cmd, [args] {
    const std::string sweep = args->sweep.empty() ? ShippedConfig("paper_sweep.yaml") : args->sweep;
    experiments::SweepSpec spec = experiments::LoadSweepSpec(sweep);
    experiments::SetSeedCount(&spec, static_cast<uint64_t>(args->seeds));
    // The ablation is a sweep of its own in DIR/noise_ablation/; a listing or a shard covers the main sweep
    // only (finalize a sharded paper with `vigil tables DIR --figures`, then run the ablation where wanted).
    const bool whole = !args->run.list && args->run.Shard().whole();
    const bool ablate = whole && !args->no_noise_ablation;
    experiments::SweepSpec noise;
    if (ablate) {  // read (and checked) before anything runs
      noise = experiments::LoadSweepSpec(args->noise_sweep.empty() ? ShippedConfig("paper_noise_sweep.yaml")
                                                                   : args->noise_sweep);
      experiments::SetSeedCount(&noise,
                                std::min<uint64_t>(noise.seeds.size(), static_cast<uint64_t>(args->seeds)));
    }
    int status = args->run.Run(spec, "paper");
    // A shard's figures would show part of the sweep: `vigil tables DIR --figures` draws them at the end.
    if (!whole) return status;
    if (ablate) status = std::max(status, RunNoiseAblation(args->run, noise));
    const auto figures = plots::RenderSweepFigures(args->run.output, plots::FigureOptions{});
    std::fprintf(stderr, "vigil paper: %zu figures -> %s\n", figures.size(),
                 (std::filesystem::path(args->run.output) / "figures").string().c_str());
    return status;
  });
}

}  // namespace vigil::app
