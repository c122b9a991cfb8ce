// `vigil map`: a glitch-sweep map (configs/glitch_map.yaml, configs/rescue_map.yaml): the two-axis sweep,
// then map.md (ATE relative to the glitch-free ATE per method and cell, experiments/sweeps/glitch_map.h) from
// what the runs recorded.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/sweep_args.h"
#include "core/format.h"
#include "core/output.h"
#include "experiments/sweeps/glitch_map.h"
#include "plots/glitch_map_figure.h"

namespace vigil::app {

void AddMapCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "map",
      "a glitch-sweep map: a sweep over two axes (first axis: glitch-free reference setting first), then "
      "map.md with each method's ATE relative to the glitch-free ATE of the same seeds, per cell");
  struct Args {
    std::string sweep;
    double target_ratio = 1.2;
    SweepArgs run;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("SWEEP", args->sweep, "the sweep file (e.g. configs/glitch_map.yaml)")->required();
  args->run.AddTo(cmd);
  cmd->add_option("--target", args->target_ratio, "ratio the best method should stay within")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            double v = 0;
            return ParseDouble(text, &v) && v > 0 && v <= 1e6 ? "" : "expected a finite ratio in (0, 1e6]";
          },
          "RATIO"));
  SetAction(cmd, [args] {
    const experiments::SweepSpec spec = experiments::LoadSweepSpec(args->sweep);
    // Checked before any run: a spec that cannot give a map is refused up front.
    experiments::CheckGlitchMapSpec(spec);
    const int status = args->run.Run(spec, "map");
    const experiments::GlitchMap map = experiments::ReadGlitchMap(args->run.output, spec);
    const std::filesystem::path out = std::filesystem::path(args->run.output) / "map.md";
    const std::string text = experiments::GlitchMapMarkdown(map, args->target_ratio);
    WriteFileAtomic(out, text);
    const std::filesystem::path figures = std::filesystem::path(args->run.output) / "figures";
    std::filesystem::create_directories(figures);
    plots::WriteGlitchMapFigure(map,
                                "ATE / glitch-free ATE (same method, same seeds): " +
                                    std::filesystem::path(args->sweep).filename().string(),
                                figures / "map.png", plots::FigureOptions{});
    std::fputs(text.c_str(), stdout);
    std::fprintf(stderr, "vigil map: -> %s, %s\n", out.string().c_str(),
                 (figures / "map.png").string().c_str());
    return status;
  });
}

}  // namespace vigil::app
