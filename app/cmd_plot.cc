// `vigil plot run|sweep|dataset DIR`: renders the figures of a run, sweep or dataset directory to PNG.
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>

#include "app/commands.h"
#include "core/output.h"
#include "plots/render.h"
#include "plots/run_data.h"

namespace vigil::app {
namespace {
namespace fs = std::filesystem;

// What a figure directory `out` must not overwrite: every entry of the input directory `dir` except `out`
// itself when it is a directory there (DIR/figures by default), and the dataset a run directory was computed
// on (never read for the figures, but a user's recording all the same).
std::vector<fs::path> PlotInputs(const std::string& kind, const fs::path& dir, const fs::path& out) {
  std::vector<fs::path> inputs;
  std::error_code ec;
  const fs::path out_resolved = fs::weakly_canonical(fs::absolute(out), ec);
  const fs::path relative = out_resolved.lexically_relative(fs::weakly_canonical(fs::absolute(dir), ec));
  if (relative.empty() || relative == "." || *relative.begin() == "..") {
    inputs.push_back(dir);  // the output is not inside `dir`
  } else {
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
      if (!e.is_directory(ec) || fs::weakly_canonical(e.path(), ec) != out_resolved)
        inputs.push_back(e.path());
  }
  if (kind == "run") {  // metrics.json names the dataset of a `vigil run --dataset` run
    if (!fs::is_regular_file(fs::path(dir) / "metrics.json", ec))
      throw InputError(
          dir.string() + ": not a run directory (no metrics.json)" +
          (fs::exists(fs::path(dir) / "imu.csv", ec) ? "; for a dataset: vigil plot dataset DIR" : ""));
    const nlohmann::json& metrics = plots::LoadRunDirectory(dir).metrics;
    if (metrics.is_object() && metrics.contains("dataset") && metrics["dataset"].is_string())
      inputs.emplace_back(metrics["dataset"].get<std::string>());
  }
  return inputs;
}

using Renderer = std::function<std::vector<std::filesystem::path>(
    const std::filesystem::path&, const std::filesystem::path&, const plots::FigureOptions&)>;

void AddPlotSubcommand(CLI::App* plot, const std::string& name, const std::string& description,
                       Renderer render) {
  auto* cmd = plot->add_subcommand(name, description);
  struct Args {
    std::string dir, output;
    plots::FigureOptions figure;
    bool force = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("DIR", args->dir, name + " directory")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", args->output,
                  "figure directory (default: DIR/figures); must not exist or be "
                  "empty, unless --force");
  cmd->add_option("--width", args->figure.width, "image width [px]")->check(CLI::Range(200, 8000));
  cmd->add_option("--height", args->figure.height, "image height [px]")->check(CLI::Range(200, 8000));
  cmd->add_option("--font", args->figure.font_file, "TrueType font file");
  cmd->add_flag("--force", args->force,
                "replace a figure directory vigil wrote (files it did not write are kept)");
  SetAction(cmd, [args, render, name] {
    plots::ValidateFigureOptions(args->figure);
    const std::filesystem::path out = args->output.empty() ? std::filesystem::path(args->dir) / "figures"
                                                           : std::filesystem::path(args->output);
    RefuseOutputOverInputs(out, PlotInputs(name, args->dir, out));
    const auto start = std::chrono::steady_clock::now();
    StagedDirectory staged(out, args->force);
    const auto written = render(args->dir, staged.path(), args->figure);
    staged.Commit();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "vigil plot %s: %zu figures (%dx%d) -> %s (%.2f s)\n", name.c_str(), written.size(),
                 args->figure.width, args->figure.height, out.c_str(), seconds);
    return 0;
  });
}

}  // namespace

void AddPlotCommand(CLI::App& root) {
  auto* plot =
      root.add_subcommand("plot", "render figures (PNG, headless) of a run, sweep or dataset directory");
  plot->require_subcommand(1);
  AddPlotSubcommand(plot, "run",
                    "figures 1-5 of a run directory (scenario, IMU, trajectory, errors, detection)",
                    plots::RenderRunFigures);
  AddPlotSubcommand(plot, "sweep", "figures 1-6 of a sweep directory (per glitch setting and method)",
                    [](const auto& dir, const auto& out, const auto& options) {
                      return plots::RenderSweepFigures(dir, out, options);
                    });
  AddPlotSubcommand(plot, "dataset",
                    "figures 1-2 of a dataset directory (scenario, IMU with/without glitches)",
                    plots::RenderDatasetFigures);
}

}  // namespace vigil::app
