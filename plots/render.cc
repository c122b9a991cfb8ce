#include "plots/render.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "gl/gl_context.h"
#include "plots/figure_data.h"

namespace vigil::plots {
namespace {

namespace fs = std::filesystem;

// One GL context and font for all figures of a call, and the files written so far.
class FigureWriter {
 public:
  FigureWriter(const fs::path& out_dir, const FigureOptions& options)
      : out_dir_(out_dir), options_(options), text_(options.font_file) {
    std::error_code ec;
    fs::create_directories(out_dir_, ec);
    if (!fs::is_directory(out_dir_))
      throw InputError(out_dir_.string() + ": cannot create the output directory");
  }

  void Write(const std::string& name, Figure figure) {
    const fs::path path = out_dir_ / name;
    WritePng(path, figure.Render(&gl_, &text_, options_.width, options_.height));
    written_.push_back(path);
  }

  // A figure whose data is missing: one line on stderr, no file.
  void Skip(const std::string& name, const std::string& why) {
    std::fprintf(stderr, "vigil: %s skipped: %s\n", name.c_str(), why.c_str());
  }

  std::vector<fs::path> written() const { return written_; }

 private:
  fs::path out_dir_;
  FigureOptions options_;
  gl::GlContext gl_;
  TextRenderer text_;
  std::vector<fs::path> written_;
};

// The run with the smallest seed (then id) among those `keep` accepts; null when none.
template <class Pred>
const RunData* FirstRun(const SweepData& sweep, Pred keep) {
  const RunData* best = nullptr;
  for (const RunData& run : sweep.runs) {
    if (!keep(run)) continue;
    if (best == nullptr || run.config.seed < best->config.seed) best = &run;
  }
  return best;
}

// Figure 1 from the run's ground truth at its frames and its landmarks.csv.
void WriteScenarioFigure(FigureWriter* writer, const RunData& run, const std::string& title) {
  std::string why;
  const std::optional<std::vector<Landmark>> landmarks = RecordedLandmarks(run, &why);
  if (run.groundtruth.empty()) why = (run.dir / "stamped_groundtruth.txt").string() + " missing";
  if (!landmarks || run.groundtruth.empty()) return writer->Skip("fig1_scenario.png", why);
  writer->Write("fig1_scenario.png", ScenarioFigure(ScenarioDataOf(run.groundtruth, *landmarks, title)));
}

// Figure 5 from the run's imu_axis.csv.
void WriteDetectionFigure(FigureWriter* writer, const RunData& run, const FigureOptions& options) {
  std::string why;
  const std::optional<experiments::ImuAxisRecord> imu = RecordedImuAxis(run, &why);
  if (!imu) return writer->Skip("fig5_detection.png", why);
  writer->Write("fig5_detection.png",
                DetectionFigure(DetectionTraceOf(run, *imu, options.detection_excerpt_s)));
}

std::string RunTitle(const RunData& run) {
  return "run " + run.id + " (" + run.method + ", " + run.glitch.Label() + ", seed " +
         std::to_string(run.config.seed) + ")";
}

}  // namespace

void ValidateFigureOptions(const FigureOptions& options) {
  if (options.width < 200 || options.width > 8000) throw InputError("--width: must be in [200, 8000]");
  if (options.height < 200 || options.height > 8000) throw InputError("--height: must be in [200, 8000]");
  if (!(options.detection_excerpt_s > 0.0)) throw InputError("detection_excerpt_s: must be positive");
  if (!fs::is_regular_file(options.font_file)) {
    throw InputError(options.font_file + ": font file missing (install fonts-dejavu-core)");
  }
}

std::vector<fs::path> RenderRunFigures(const fs::path& run_dir, const fs::path& out_dir,
                                       const FigureOptions& options) {
  ValidateFigureOptions(options);
  const RunData run = LoadRunDirectory(run_dir);
  std::string why;
  const std::optional<experiments::ImuAxisRecord> imu = RecordedImuAxis(run, &why);
  FigureWriter writer(out_dir, options);
  WriteScenarioFigure(&writer, run, "Scenario of " + RunTitle(run));
  if (imu) {
    writer.Write("fig2_glitches.png", GlitchFigure({ImuTraceOf(*imu, run.glitch.Label())}));
  } else {
    writer.Skip("fig2_glitches.png", why);
  }
  if (!run.groundtruth.empty()) {
    writer.Write("fig3_trajectories.png", TrajectoryFigure({TrajectoryPanelOf(run.glitch.Label(), {&run})}));
  }
  const RelativeErrorRow row = RelativeErrorRowOfRun(run.glitch.Label(), run);
  if (!row.methods.empty()) {
    writer.Write("fig4_relative_error.png",
                 RelativeErrorFigure({row}, "box: mean ± std of the run's segments, whiskers: min and max"));
  }
  if (run.config.detector.type != detectors::DetectorType::kNone) WriteDetectionFigure(&writer, run, options);
  return writer.written();
}

std::vector<fs::path> RenderSweepFigures(const fs::path& sweep_dir, const FigureOptions& options) {
  return RenderSweepFigures(sweep_dir, sweep_dir / "figures", options);
}

std::vector<fs::path> RenderSweepFigures(const fs::path& sweep_dir, const fs::path& out_dir,
                                         const FigureOptions& options) {
  ValidateFigureOptions(options);
  const SweepData sweep = LoadSweepDirectory(sweep_dir);
  FigureWriter writer(out_dir, options);

  WriteScenarioFigure(&writer, *FirstRun(sweep, [](const RunData&) { return true; }),
                      "Simulated trajectory and landmarks");

  std::vector<ImuTrace> traces;
  std::string traces_missing;
  std::vector<TrajectoryPanel> trajectory_rows;
  std::vector<RelativeErrorRow> error_rows;
  for (const GlitchSetting& setting : sweep.settings) {
    const RunData* rep = FirstRun(sweep, [&](const RunData& r) { return r.glitch == setting; });
    std::string why;
    if (const auto imu = RecordedImuAxis(*rep, &why)) {
      traces.push_back(ImuTraceOf(*imu, setting.Label()));
    } else if (traces_missing.empty()) {
      traces_missing = why;
    }
    std::vector<const RunData*> per_method, all;
    for (const std::string& method : sweep.methods) {
      const RunData* r = FirstRun(sweep, [&](const RunData& x) {
        return x.glitch == setting && x.method == method && x.ok() && !x.estimate.empty();
      });
      if (r != nullptr) per_method.push_back(r);
    }
    for (const RunData& r : sweep.runs) {
      if (r.glitch == setting) all.push_back(&r);
    }
    trajectory_rows.push_back(TrajectoryPanelOf(setting.Label(), per_method));
    error_rows.push_back(RelativeErrorRowOfRuns(setting.Label(), all));
  }
  if (traces_missing.empty()) {
    writer.Write("fig2_glitches.png", GlitchFigure(traces));
  } else {
    writer.Skip("fig2_glitches.png", traces_missing);
  }
  // Trajectories only when some run kept them (a sweep may disable writing them).
  if (std::any_of(trajectory_rows.begin(), trajectory_rows.end(),
                  [](const TrajectoryPanel& p) { return !p.estimates.empty(); })) {
    writer.Write("fig3_trajectories.png", TrajectoryFigure(trajectory_rows));
  }
  writer.Write(
      "fig4_relative_error.png",
      RelativeErrorFigure(error_rows, "box: quartiles over runs of each run's mean error, whiskers 1.5 IQR"));

  // Detection: the strongest glitch setting, DTW when the sweep has it, else any detector.
  const RunData* detected = nullptr;
  for (auto it = sweep.settings.rbegin(); it != sweep.settings.rend() && detected == nullptr; ++it) {
    for (const char* preferred : {"dtw", ""}) {
      if (detected != nullptr) break;
      detected = FirstRun(sweep, [&](const RunData& r) {
        return r.glitch == *it && r.config.detector.type != detectors::DetectorType::kNone &&
               (preferred[0] == '\0' || r.method == preferred);
      });
    }
  }
  if (detected != nullptr) WriteDetectionFigure(&writer, *detected, options);

  std::vector<std::string> labels;
  for (const GlitchSetting& s : sweep.settings) labels.push_back(s.Label());
  writer.Write("fig6_summary.png", SummaryFigure(labels, sweep.methods, SummaryCellsOf(sweep)));
  return writer.written();
}

std::vector<fs::path> RenderDatasetFigures(const fs::path& dataset_dir, const fs::path& out_dir,
                                           const FigureOptions& options) {
  ValidateFigureOptions(options);
  // A vigil dataset or a EuRoC folder (core/euroc.h); the latter has no landmarks and may lack ground truth.
  const Recording recording = ReadRecording(dataset_dir);
  const Dataset& data = recording.dataset;
  ImuAxis axis = ImuAxis::kAz;
  std::string label = "IMU";
  if (fs::is_regular_file(dataset_dir / "config.yaml")) {
    const experiments::RunConfig config = experiments::LoadRunConfig((dataset_dir / "config.yaml").string());
    axis = GlitchedAxis(config);
    label = GlitchSettingOf(config).Label();
  }
  FigureWriter writer(out_dir, options);
  fs::path named = fs::absolute(dataset_dir).lexically_normal();
  if (!named.has_filename()) named = named.parent_path();  // "DIR/"
  if (recording.has_groundtruth)
    writer.Write("fig1_scenario.png",
                 ScenarioFigure(ScenarioDataOf(data, "Scenario of " + named.filename().string())));
  else
    writer.Skip("fig1_scenario.png", dataset_dir.string() + " has no ground truth");
  writer.Write("fig2_glitches.png", GlitchFigure({ImuTraceOf(data, axis, label)}));
  return writer.written();
}

}  // namespace vigil::plots
