// `vigil roc`: a detector ROC (configs/roc_paper.yaml, configs/roc_rescue.yaml): the sweep of (detector,
// threshold) methods, then roc.md and figures/roc.png from what the runs recorded
// (experiments/sweeps/detection_roc.h).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/sweep_args.h"
#include "core/output.h"
#include "experiments/sweeps/detection_roc.h"
#include "plots/roc_figure.h"

namespace vigil::app {

void AddRocCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "roc",
      "a detector ROC: a sweep whose methods are <detector>_<point> thresholds, then roc.md and "
      "figures/roc.png (true-positive vs false-positive rate per sample)");
  struct Args {
    std::string sweep;
    SweepArgs run;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("SWEEP", args->sweep, "the sweep file (e.g. configs/roc_paper.yaml)")->required();
  args->run.AddTo(cmd);
  SetAction(cmd, [args] {
    const experiments::SweepSpec spec = experiments::LoadSweepSpec(args->sweep);
    experiments::CheckRocMethodLabels(spec);  // before any run
    const int status = args->run.Run(spec, "roc");
    const auto curves = experiments::ReadDetectionRoc(args->run.output, spec);
    const std::filesystem::path dir(args->run.output);
    const std::string text = experiments::DetectionRocMarkdown(curves);
    WriteFileAtomic(dir / "roc.md", text);
    std::filesystem::create_directories(dir / "figures");
    plots::WriteRocFigure(curves, "Detector ROC: " + std::filesystem::path(args->sweep).filename().string(),
                          dir / "figures" / "roc.png", plots::FigureOptions{});
    std::fputs(text.c_str(), stdout);
    std::fprintf(stderr, "vigil roc: -> %s, %s\n", (dir / "roc.md").string().c_str(),
                 (dir / "figures" / "roc.png").string().c_str());
    return status;
  });
}

}  // namespace vigil::app
