// Figures of synthetic run, sweep and dataset directories: files, sizes, content, determinism, errors.
#include "plots/render.h"

#include <algorithm>
#include <cstdlib>

#include <gtest/gtest.h>

#include "core/dataset.h"
#include "core/euroc.h"
#include "core/output.h"
#include "detectors/detector.h"
#include "experiments/commands/run_command.h"
#include "experiments/runs/detection_stage.h"
#include "experiments/runs/imu_axis_record.h"
#include "plots/image.h"
#include "plots/run_data.h"
#include "sim/simulator.h"
#include "tests/core/test_util.h"
#include "tests/plots/synthetic_runs.h"

namespace vigil::plots {
namespace {

namespace fs = std::filesystem;

// Decodes `path`, checks its size and that it is not blank (many colours, a good share of non-white pixels).
void ExpectRealFigure(const fs::path& path, int width, int height) {
  SCOPED_TRACE(path.string());
  const Image image = DecodePng(ReadFile(path));
  ASSERT_EQ(image.width, width);
  ASSERT_EQ(image.height, height);
  std::size_t non_white = 0;
  std::vector<bool> seen(1 << 15, false);
  int colours = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    const uint8_t r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
    if (r < 250 || g < 250 || b < 250) ++non_white;
    const int key = (r >> 3) << 10 | (g >> 3) << 5 | (b >> 3);
    if (!seen[key]) {
      seen[key] = true;
      ++colours;
    }
  }
  EXPECT_GT(non_white, image.rgba.size() / 4 / 100);  // > 1 % ink
  EXPECT_GT(colours, 20);                             // lines, text anti-aliasing, several series
}

std::vector<std::string> Names(const std::vector<fs::path>& paths) {
  std::vector<std::string> names;
  for (const auto& p : paths) names.push_back(p.filename().string());
  return names;
}

FigureOptions Small() {
  FigureOptions options;
  options.width = 640;
  options.height = 400;
  return options;
}

TEST(RenderSweep, WritesAllSixFiguresDeterministically) {
  vigil::testing::TempDir tmp;
  testing::WriteSyntheticSweep(tmp.path() / "sweep", {{true, 1.0, 0.5}, {true, 4.0, 2.0}}, 2, 4.0);
  const auto written = RenderSweepFigures(tmp.path() / "sweep", Small());
  EXPECT_EQ(Names(written),
            (std::vector<std::string>{"fig1_scenario.png", "fig2_glitches.png", "fig3_trajectories.png",
                                      "fig4_relative_error.png", "fig5_detection.png", "fig6_summary.png"}));
  for (const auto& p : written) {
    EXPECT_EQ(p.parent_path(), tmp.path() / "sweep" / "figures");
    ExpectRealFigure(p, 640, 400);
  }
  // VIGIL_PLOTS_TEST_OUTPUT=DIR keeps full-size figures of this sweep for a look.
  if (const char* keep = std::getenv("VIGIL_PLOTS_TEST_OUTPUT")) {
    RenderSweepFigures(tmp.path() / "sweep", fs::path(keep) / "sweep", FigureOptions());
  }
  // Same input, same bytes.
  const std::string before = ReadFile(written[5]) + ReadFile(written[2]);
  const auto again = RenderSweepFigures(tmp.path() / "sweep", tmp.path() / "again", Small());
  EXPECT_EQ(ReadFile(again[5]) + ReadFile(again[2]), before);
  // No temporary files left beside the figures.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(tmp.path() / "sweep" / "figures"))
    files += entry.is_regular_file();
  EXPECT_EQ(files, 6);
}

TEST(RenderSweep, DefaultSizeIs1600By1000) {
  vigil::testing::TempDir tmp;
  testing::WriteSyntheticSweep(tmp.path() / "sweep", {{false, 0.0, 1.0}}, 1, 3.0);
  const FigureOptions options;
  EXPECT_EQ(options.width, 1600);
  EXPECT_EQ(options.height, 1000);
  const auto written = RenderSweepFigures(tmp.path() / "sweep", options);
  ASSERT_FALSE(written.empty());
  ExpectRealFigure(written.back(), 1600, 1000);
}

TEST(RenderSweep, RejectsWhatIsNotASweep) {
  vigil::testing::TempDir tmp;
  EXPECT_NE(vigil::testing::InputErrorOf([&] { RenderSweepFigures(tmp.path(), Small()); }).find("runs"),
            std::string::npos);
  fs::create_directories(tmp.path() / "runs" / "half-written.tmp-1");
  EXPECT_NE(vigil::testing::InputErrorOf([&] { RenderSweepFigures(tmp.path(), Small()); }).find("no run"),
            std::string::npos);
  FigureOptions bad = Small();
  bad.width = 10;
  EXPECT_NE(vigil::testing::InputErrorOf([&] { RenderSweepFigures(tmp.path(), bad); }).find("--width"),
            std::string::npos);
  bad = Small();
  bad.font_file = (tmp.path() / "missing.ttf").string();
  EXPECT_NE(vigil::testing::InputErrorOf([&] { RenderSweepFigures(tmp.path(), bad); }).find("missing.ttf"),
            std::string::npos);
}

TEST(RenderRun, WritesFiguresOneToFive) {
  vigil::testing::TempDir tmp;
  const auto config = testing::SyntheticConfig({true, 3.0, 1.0}, detectors::DetectorType::kThreshold, 7, 4.0);
  testing::WriteSyntheticRun(tmp.path() / "run", config, sim::Simulate(config.sim, config.seed));
  const auto written = RenderRunFigures(tmp.path() / "run", tmp.path() / "figs", Small());
  EXPECT_EQ(Names(written),
            (std::vector<std::string>{"fig1_scenario.png", "fig2_glitches.png", "fig3_trajectories.png",
                                      "fig4_relative_error.png", "fig5_detection.png"}));
  for (const auto& p : written) ExpectRealFigure(p, 640, 400);
}

// The contract end to end: a real run directory written by the experiments' runner (estimator included).
TEST(RenderRun, RealRunDirectory) {
  vigil::testing::TempDir tmp;
  const std::string paper = std::string(VIGIL_SOURCE_DIR) + "/configs/paper.yaml";
  experiments::RunToDirectory(paper,
                              {"duration_s=4", "glitch.enabled=true", "glitch.mean=3", "glitch.std=1",
                               "glitch.rate=0.02", "detector.type=threshold"},
                              experiments::RunOptions{}, tmp.path() / "run", false);
  const auto written = RenderRunFigures(tmp.path() / "run", tmp.path() / "figs", Small());
  EXPECT_EQ(Names(written),
            (std::vector<std::string>{"fig1_scenario.png", "fig2_glitches.png", "fig3_trajectories.png",
                                      "fig4_relative_error.png", "fig5_detection.png"}));
  for (const auto& p : written) ExpectRealFigure(p, 640, 400);
  if (const char* keep = std::getenv("VIGIL_PLOTS_TEST_OUTPUT")) {
    RenderRunFigures(tmp.path() / "run", fs::path(keep) / "run", FigureOptions());
  }
}

// A run records what its figures draw: the recorded IMU axis (raw, clean, the mitigation the run applied,
// its flags) and the landmarks of the recording it consumed (here a dataset simulated with another seed than
// the config's, so a re-simulation would differ). The run directory alone renders the same figures after
// the dataset is gone and the directory has moved.
TEST(RenderRun, DatasetRunIsPlottedFromWhatItRecorded) {
  vigil::testing::TempDir tmp;
  const std::string paper = std::string(VIGIL_SOURCE_DIR) + "/configs/paper.yaml";
  const std::vector<std::string> overrides = {"duration_s=3", "glitch.enabled=true", "glitch.mean=30",
                                              "glitch.std=1", "detector.type=threshold"};
  experiments::RunConfig config = experiments::LoadRunConfig(paper, overrides);
  sim::SimulateToDirectory(config.sim, 9, config::ToYaml(config), tmp.path() / "ds", false);
  experiments::RunOptions options;
  options.dataset_dir = tmp.path() / "ds";
  experiments::RunToDirectory(paper, overrides, options, tmp.path() / "run", false);

  const Dataset recorded = ReadDataset(tmp.path() / "ds");
  const experiments::ImuAxisRecord imu =
      experiments::ReadImuAxisCsv((tmp.path() / "run" / experiments::kImuAxisFile).string());
  // The detector as the run resolved it (the paper's threshold calibrates its bounds on the recording's own
  // clean stream first).
  const experiments::CalibrationReference reference{recorded.imu_clean, "imu_clean.csv"};
  const detectors::DetectionResult applied =
      detectors::DetectAndMitigate(experiments::ResolveDetectorOptions(config, &reference), recorded.imu);
  EXPECT_EQ(imu.axis, ImuAxis::kAz);
  ASSERT_EQ(imu.raw.size(), recorded.imu.size());
  ASSERT_EQ(imu.clean.size(), recorded.imu.size());
  int flagged = 0;
  for (std::size_t i = 0; i < imu.raw.size(); ++i) {
    EXPECT_EQ(imu.t_ns[i], recorded.imu[i].t_ns);
    EXPECT_EQ(imu.raw[i], recorded.imu[i].a_B.z()) << i;
    EXPECT_EQ(imu.clean[i], recorded.imu_clean[i].a_B.z()) << i;
    EXPECT_EQ(imu.mitigated[i], applied.cleaned[i].a_B.z()) << i;
    EXPECT_EQ(imu.flagged[i], applied.flagged[i]) << i;
    flagged += imu.flagged[i];
  }
  EXPECT_GT(flagged, 0);
  EXPECT_EQ(ReadLandmarksCsv((tmp.path() / "run" / "landmarks.csv").string()).size(),
            recorded.landmarks.size());

  const auto first = RenderRunFigures(tmp.path() / "run", tmp.path() / "figs", Small());
  ASSERT_EQ(first.size(), 5u);
  fs::remove_all(tmp.path() / "ds");
  fs::create_directories(tmp.path() / "elsewhere");
  fs::rename(tmp.path() / "run", tmp.path() / "elsewhere" / "run");  // same name: figure 1's title has it
  const auto again = RenderRunFigures(tmp.path() / "elsewhere" / "run", tmp.path() / "figs2", Small());
  ASSERT_EQ(Names(again), Names(first));
  for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(ReadFile(again[i]), ReadFile(first[i])) << i;
}

// A run directory without figure data (an older vigil, --no-figure-data): the figures that need it are
// skipped with one line each, the others are drawn; nothing is re-simulated.
TEST(RenderRun, RunWithoutFigureDataSkipsThoseFigures) {
  vigil::testing::TempDir tmp;
  const auto config = testing::SyntheticConfig({true, 3.0, 1.0}, detectors::DetectorType::kThreshold, 7, 3.0);
  testing::WriteSyntheticRun(tmp.path() / "run", config, sim::Simulate(config.sim, config.seed),
                             /*failed=*/false, /*with_figure_data=*/false);
  ::testing::internal::CaptureStderr();
  const auto written = RenderRunFigures(tmp.path() / "run", tmp.path() / "figs", Small());
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(Names(written), (std::vector<std::string>{"fig3_trajectories.png", "fig4_relative_error.png"}));
  EXPECT_NE(err.find("vigil: fig1_scenario.png skipped: " + (tmp.path() / "run" / "landmarks.csv").string() +
                     " missing"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("vigil: fig2_glitches.png skipped: "), std::string::npos) << err;
  EXPECT_NE(err.find("vigil: fig5_detection.png skipped: " + (tmp.path() / "run" / "imu_axis.csv").string()),
            std::string::npos)
      << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 3);

  // A sweep of such runs: figures 1, 2 and 5 skipped the same way.
  fs::create_directories(tmp.path() / "sweep" / "runs");
  fs::rename(tmp.path() / "run", tmp.path() / "sweep" / "runs" / "r000");
  ::testing::internal::CaptureStderr();
  const auto sweep = RenderSweepFigures(tmp.path() / "sweep", Small());
  const std::string sweep_err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(Names(sweep), (std::vector<std::string>{"fig3_trajectories.png", "fig4_relative_error.png",
                                                    "fig6_summary.png"}));
  EXPECT_EQ(std::count(sweep_err.begin(), sweep_err.end(), '\n'), 3) << sweep_err;
}

// A bad figure-data file is an input error naming it, not a skipped figure.
TEST(RenderRun, BadImuAxisNamesTheFile) {
  vigil::testing::TempDir tmp;
  const auto config = testing::SyntheticConfig({true, 3.0, 1.0}, detectors::DetectorType::kThreshold, 7, 3.0);
  testing::WriteSyntheticRun(tmp.path() / "run", config, sim::Simulate(config.sim, config.seed));
  WriteFileAtomic(tmp.path() / "run" / "imu_axis.csv",
                  "#timestamp [ns],raw az,mitigated az,flagged\n1,2,3,4\n");
  const std::string error =
      vigil::testing::InputErrorOf([&] { RenderRunFigures(tmp.path() / "run", tmp.path() / "f", Small()); });
  EXPECT_NE(error.find("imu_axis.csv:2: flagged: must be 0 or 1"), std::string::npos) << error;
}

TEST(RenderRun, BadMetricsNamesTheFile) {
  vigil::testing::TempDir tmp;
  const auto config = testing::SyntheticConfig({false, 0.0, 1.0}, detectors::DetectorType::kNone, 1, 3.0);
  testing::WriteSyntheticRun(tmp.path() / "run", config, sim::Simulate(config.sim, config.seed));
  WriteFileAtomic(tmp.path() / "run" / "metrics.json", "{ not json");
  EXPECT_NE(vigil::testing::InputErrorOf([&] {
              RenderRunFigures(tmp.path() / "run", tmp.path() / "f", Small());
            }).find("metrics.json"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(tmp.path() / "f" / "fig1_scenario.png"));
}

TEST(RenderDataset, WritesScenarioAndGlitches) {
  vigil::testing::TempDir tmp;
  auto config = testing::SyntheticConfig({true, 2.0, 1.0}, detectors::DetectorType::kNone, 3, 3.0);
  sim::SimulateToDirectory(config.sim, config.seed, config::ToYaml(config), tmp.path() / "data", false);
  const auto written = RenderDatasetFigures(tmp.path() / "data", tmp.path() / "figs", Small());
  EXPECT_EQ(Names(written), (std::vector<std::string>{"fig1_scenario.png", "fig2_glitches.png"}));
  for (const auto& p : written) ExpectRealFigure(p, 640, 400);
}

// A EuRoC folder as published (mav0/ only: no landmarks, no config.yaml): figure 1 from its ground truth, and
// without ground truth figure 2 alone.
TEST(RenderDataset, EurocFolderWithAndWithoutGroundTruth) {
  vigil::testing::TempDir tmp;
  const auto config = testing::SyntheticConfig({false, 0.0, 1.0}, detectors::DetectorType::kNone, 3, 3.0);
  const Dataset data = sim::Simulate(config.sim, config.seed);
  fs::create_directories(tmp.path() / "euroc");
  WriteEuroc(tmp.path() / "euroc", data, sim::ImuSensorOf(config.sim.imu), {});
  fs::remove_all(tmp.path() / "euroc" / "mav0" / "cam0");  // the figures need no camera
  const auto written = RenderDatasetFigures(tmp.path() / "euroc", tmp.path() / "figs", Small());
  EXPECT_EQ(Names(written), (std::vector<std::string>{"fig1_scenario.png", "fig2_glitches.png"}));
  for (const auto& p : written) ExpectRealFigure(p, 640, 400);
  fs::remove_all(tmp.path() / "euroc" / "mav0" / "state_groundtruth_estimate0");
  const auto imu_only = RenderDatasetFigures(tmp.path() / "euroc" / "mav0", tmp.path() / "figs2", Small());
  EXPECT_EQ(Names(imu_only), (std::vector<std::string>{"fig2_glitches.png"}));
}

}  // namespace
}  // namespace vigil::plots
