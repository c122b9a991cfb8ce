// Rendering the figures of a run, sweep or dataset directory into PNG files.
//
// `vigil plot run|sweep|dataset DIR` and `vigil paper` call these. Each writes its figures atomically into
// the output directory (created when missing; figures of the same name are replaced) and returns their paths.
// Bad or missing input throws InputError naming the file.
//
// Figure files: fig1_scenario.png, fig2_glitches.png, fig3_trajectories.png, fig4_relative_error.png,
// fig5_detection.png, fig6_summary.png. A sweep gets all six (3 only when some run kept its trajectories, 5
// only when some run used a detector); a run directory 1-5 as far as its data allows (3 needs the
// trajectories, 4 metrics.json, 5 a detector); a dataset directory 1 and 2. A dataset directory is a vigil
// dataset or a EuRoC folder as published (core/euroc.h's ReadRecording: its ground truth, no landmarks); one
// without ground truth gets figure 2 only, with one line "vigil: fig1_scenario.png skipped: DIR has no ground
// truth".
//
// Figures draw only what the directories hold, never re-simulating or re-running a detector: 1 needs the
// run's stamped_groundtruth.txt and landmarks.csv, 2 and 5 its imu_axis.csv (run.h's figure data; for a
// sweep, those of its lowest-seed runs). A run directory without them (written by an older vigil or with
// --no-figure-data) gets the other figures and one line "vigil: FIGURE skipped: FILE missing (...)" on
// stderr per figure left out.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "plots/text.h"

namespace vigil::plots {

struct FigureOptions {
  int width = 1600;   // [px]
  int height = 1000;  // [px]
  std::string font_file = kDefaultFontFile;
  double detection_excerpt_s = 3.0;  // length of the zoomed window of figure 5
};

// InputError when the size is not in [200, 8000] or the font cannot be read.
void ValidateFigureOptions(const FigureOptions& options);

std::vector<std::filesystem::path> RenderRunFigures(const std::filesystem::path& run_dir,
                                                    const std::filesystem::path& out_dir,
                                                    const FigureOptions& options);
// Into sweep_dir/figures (the API `vigil paper` calls).
std::vector<std::filesystem::path> RenderSweepFigures(const std::filesystem::path& sweep_dir,
                                                      const FigureOptions& options);
std::vector<std::filesystem::path> RenderSweepFigures(const std::filesystem::path& sweep_dir,
                                                      const std::filesystem::path& out_dir,
                                                      const FigureOptions& options);
std::vector<std::filesystem::path> RenderDatasetFigures(const std::filesystem::path& dataset_dir,
                                                        const std::filesystem::path& out_dir,
                                                        const FigureOptions& options);

}  // namespace vigil::plots
