#include "experiments/commands/run_command.h"

#include <gtest/gtest.h>

#include "core/dataset.h"
#include "core/output.h"
#include "evaluation/evaluate_trajectory.h"
#include "experiments/runs/imu_axis_record.h"
#include "sim/simulator.h"
#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using testing::InputErrorOf;
using testing::TempDir;

const std::string kPaper = std::string(VIGIL_SOURCE_DIR) + "/configs/paper.yaml";
const std::vector<std::string> kShort = {"duration_s=4"};
// For tests that only check files and errors.
const std::vector<std::string> kTiny = {"duration_s=1.5"};

std::vector<std::string> With(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(Run, ShortRunEndToEnd) {
  TempDir tmp;
  const fs::path dir = tmp.path() / "run";
  const nlohmann::json m = RunToDirectory(kPaper, kShort, RunOptions{}, dir, false);
  for (const char* f :
       {"config.yaml", "stamped_groundtruth.txt", "stamped_traj_estimate.txt", "metrics.json"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_FALSE(fs::exists(dir / "detections.csv"));  // detector none
  EXPECT_EQ(nlohmann::json::parse(ReadFile(dir / "metrics.json")), m);

  EXPECT_EQ(m["status"], "ok") << m["failure_reason"];
  EXPECT_EQ(m["seed"], 1);
  EXPECT_EQ(m["duration_s"], 4.0);
  for (const char* key : {"status", "failure_reason", "seed", "duration_s", "wall_time_s", "estimator", "ate",
                          "relative", "detection", "coverage"})
    EXPECT_TRUE(m.contains(key)) << key;
  for (const char* key : {"simulate", "detect", "estimate", "evaluate", "total"})
    EXPECT_TRUE(m["wall_time_s"][key].is_number()) << key;
  for (const char* key : {"init", "initialized_at_s", "resets", "frames", "keyframes"})
    EXPECT_TRUE(m["estimator"].contains(key)) << key;
  EXPECT_EQ(m["estimator"]["init"], "vins");  // configs/paper.yaml starts from nothing
  EXPECT_EQ(m["ate"]["align"], "posyaw");
  EXPECT_EQ(m["relative"].size(), 5u);
  EXPECT_EQ(m["relative"][0]["distance_m"], 7.0);
  EXPECT_GT(m["relative"][0]["trans_m"]["n"].get<int>(), 10);
  EXPECT_EQ(m["detection"]["detector"], "none");
  // A loose bound: the estimator on 4 s of the paper scenario stays within decimetres.
  EXPECT_LT(m["ate"]["trans_m"]["rmse"].get<double>(), 0.3);
  // The ground truth from the initialization on is covered (the first window of 16 frames at 10 Hz: 1.5 s).
  const double tracked_s = 4.0 - m["estimator"]["initialized_at_s"].get<double>();
  EXPECT_GT(tracked_s, 2.0);
  EXPECT_GT(m["coverage"].get<double>(), 0.95 * tracked_s / 4.0);

  // The written files are the evaluated ones: evaluating them again (`vigil eval`) gives the same numbers.
  const Trajectory gt = ReadTumTrajectory((dir / "stamped_groundtruth.txt").string());
  const Trajectory est = ReadTumTrajectory((dir / "stamped_traj_estimate.txt").string());
  EXPECT_EQ(gt.size(), 121u);  // every camera frame of 4 s at 30 Hz
  const evaluation::TrajectoryEvaluation again =
      evaluation::EvaluateTrajectory(gt, est, evaluation::EvaluationOptions{});
  EXPECT_NEAR(again.ate_trans_m.rmse, m["ate"]["trans_m"]["rmse"].get<double>(), 1e-9);
  // config.yaml reproduces the run's configuration.
  EXPECT_EQ(ReadFile(dir / "config.yaml"), [] {
    RunConfig c = LoadRunConfig(kPaper, kShort);
    return config::ToYaml(c);
  }());
}

TEST(Run, DatasetRunEqualsTheSimulatedRun) {
  TempDir tmp;
  const std::vector<std::string> overrides =
      With(kShort,
           // A detector without calibration: a dataset run calibrates on the recording's imu_clean.csv, a
           // simulated run on a glitch-free simulation (docs/detection.md), so the paper's threshold differs.
           {"glitch.enabled=true", "glitch.mean=50", "glitch.std=10", "detector.type=relative_threshold",
            "estimator.solver.max_time_s=0"});  // no wall-clock cap: the same input gives the same estimate
  RunConfig c = LoadRunConfig(kPaper, overrides);
  sim::SimulateToDirectory(c.sim, c.seed, config::ToYaml(c), tmp.path() / "ds", false);
  const nlohmann::json simulated = RunToDirectory(kPaper, overrides, RunOptions{}, tmp.path() / "a", false);
  RunOptions from_dataset;
  from_dataset.dataset_dir = tmp.path() / "ds";
  const nlohmann::json read = RunToDirectory(kPaper, overrides, from_dataset, tmp.path() / "b", false);
  // The files hold the same numbers, bit for bit.
  EXPECT_NEAR(read["ate"]["trans_m"]["rmse"].get<double>(), simulated["ate"]["trans_m"]["rmse"].get<double>(),
              1e-9);
  EXPECT_NEAR(read["ate"]["rot_deg"]["rmse"].get<double>(), simulated["ate"]["rot_deg"]["rmse"].get<double>(),
              1e-9);
  EXPECT_EQ(read["detection"], simulated["detection"]);
  EXPECT_GT(read["detection"]["recall"].get<double>(), 0.8);
  // detections.csv: a header and one row per IMU sample.
  const std::string csv = ReadFile(tmp.path() / "b" / "detections.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 802);
}

TEST(Run, ADivergingEstimatorStillWritesItsMetrics) {
  // Huge glitches on every axis of 30 % of the samples and no detector: the estimator cannot keep up.
  TempDir tmp;
  const nlohmann::json m =
      RunToDirectory(kPaper,
                     With(kTiny, {"glitch.enabled=true", "glitch.mean=500", "glitch.rate=0.3",
                                  "glitch.axes=[ax, ay, az, wx, wy, wz]", "estimator.init=groundtruth"}),
                     RunOptions{}, tmp.path() / "run", false);
  EXPECT_TRUE(m["status"] == "failed" || m["estimator"]["resets"].get<int>() > 0) << m.dump();
  if (m["status"] == "failed") {
    EXPECT_FALSE(m["failure_reason"].get<std::string>().empty());
    EXPECT_LT(m["coverage"].get<double>(),
              1.0);  // the evaluation covers what was estimated before the failure
  }
  EXPECT_EQ(nlohmann::json::parse(ReadFile(tmp.path() / "run" / "metrics.json")), m);
  EXPECT_TRUE(fs::exists(tmp.path() / "run" / "stamped_traj_estimate.txt"));
}

TEST(Run, SameConfigGivesIdenticalFilesWithoutASolverTimeCap) {
  // What sweeps rely on (-j 1 == -j 8). The default solver time cap (max_time_s, as VINS-Mono) makes the
  // result depend on the machine's load; without it a run is a pure function of its config.
  TempDir tmp;
  const auto overrides =
      With(kTiny, {"estimator.solver.max_time_s=0", "glitch.enabled=true", "detector.type=dtw"});
  RunToDirectory(kPaper, overrides, RunOptions{}, tmp.path() / "a", false);
  RunToDirectory(kPaper, overrides, RunOptions{}, tmp.path() / "b", false);
  for (const char* f : {"config.yaml", "stamped_groundtruth.txt", "stamped_traj_estimate.txt",
                        "detections.csv", "landmarks.csv", "imu_axis.csv"})
    EXPECT_EQ(ReadFile(tmp.path() / "a" / f), ReadFile(tmp.path() / "b" / f)) << f;
  auto a = nlohmann::json::parse(ReadFile(tmp.path() / "a" / "metrics.json"));
  auto b = nlohmann::json::parse(ReadFile(tmp.path() / "b" / "metrics.json"));
  for (auto* m : {&a, &b}) {  // wall-clock times are the only difference
    m->erase("wall_time_s");
    m->at("estimator").erase("timing");
  }
  EXPECT_EQ(a, b);
}

std::vector<std::string> FileNames(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(Run, NoTrajectoriesNoFigureDataWritesOnlyConfigAndMetrics) {
  TempDir tmp;
  RunOptions options;
  options.write_trajectories = false;
  options.write_figure_data = false;
  RunToDirectory(kPaper, With(kTiny, {"detector.type=hampel"}), options, tmp.path() / "run", false);
  EXPECT_EQ(FileNames(tmp.path() / "run"),
            (std::vector<std::string>{".vigil-output", "config.yaml", "metrics.json"}));
}

// detections.csv only when a detector ran; the figure data (landmarks, the glitched IMU axis raw / clean /
// mitigated with the flags) always, unless switched off.
TEST(Run, WritesFigureDataAndDetectionsOnlyWithADetector) {
  TempDir tmp;
  RunToDirectory(kPaper, With(kTiny, {"glitch.enabled=true", "glitch.axes=[wy]"}), RunOptions{},
                 tmp.path() / "none", false);
  EXPECT_EQ(
      FileNames(tmp.path() / "none"),
      (std::vector<std::string>{".vigil-output", "config.yaml", "imu_axis.csv", "landmarks.csv",
                                "metrics.json", "stamped_groundtruth.txt", "stamped_traj_estimate.txt"}));
  const ImuAxisRecord none = ReadImuAxisCsv((tmp.path() / "none" / "imu_axis.csv").string());
  EXPECT_EQ(none.axis, ImuAxis::kWy);
  EXPECT_EQ(none.mitigated, none.raw);
  EXPECT_NE(none.clean, none.raw);
  RunOptions no_trajectories;
  no_trajectories.write_trajectories = false;
  RunToDirectory(kPaper, With(kTiny, {"glitch.enabled=true", "detector.type=threshold"}), no_trajectories,
                 tmp.path() / "threshold", false);
  EXPECT_EQ(FileNames(tmp.path() / "threshold"),
            (std::vector<std::string>{".vigil-output", "config.yaml", "imu_axis.csv", "landmarks.csv",
                                      "metrics.json"}));
  const ImuAxisRecord threshold = ReadImuAxisCsv((tmp.path() / "threshold" / "imu_axis.csv").string());
  EXPECT_EQ(threshold.axis, ImuAxis::kAz);
  EXPECT_NE(threshold.mitigated, threshold.raw);
  int flagged = 0;
  for (uint8_t f : threshold.flagged) flagged += f;
  EXPECT_GT(flagged, 0);
}

TEST(Run, BadInputWritesNothing) {
  TempDir tmp;
  const fs::path dir = tmp.path() / "run";
  EXPECT_EQ(InputErrorOf([&] { RunToDirectory(kPaper, {"glitch.rate=2"}, RunOptions{}, dir, false); }),
            "--set: glitch.rate: must be in [0, 1]");
  EXPECT_NE(InputErrorOf([&] {
              RunToDirectory(kPaper, {"detector.threshold.lower=[1, 2]"}, RunOptions{}, dir, false);
            }),
            "");
  const std::string bad = tmp.File("bad.yaml", "seed: 1\nestimator:\n  init: magic\n");
  EXPECT_NE(InputErrorOf([&] { RunToDirectory(bad, {}, RunOptions{}, dir, false); }).find("bad.yaml:3"),
            std::string::npos);
  // An external estimator that needs images on a simulated run: blamed on the --set that asked for them.
  EXPECT_EQ(InputErrorOf([&] {
              RunToDirectory(kPaper,
                             {"estimator.backend=external", "estimator.external.command=[/bin/true]",
                              "estimator.external.input=images"},
                             RunOptions{}, dir, false);
            }).rfind("--set estimator.external.input=images: estimator.external.input: images: ", 0),
            0u);
  EXPECT_EQ(InputErrorOf([&] { RunToDirectory(kPaper, kShort, RunOptions{}, "", false); }),
            "-o: the output path is empty (name a directory to write)");
  RunOptions missing;
  missing.dataset_dir = tmp.path() / "no_such_dataset";
  EXPECT_NE(InputErrorOf([&] { RunToDirectory(kPaper, kShort, missing, dir, false); }), "");
  // Neither the run directory nor a staging sibling is left behind.
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(tmp.path())) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, (std::vector<std::string>{"bad.yaml"}));
}

TEST(Run, ForceReplacesOnlyARunDirectoryVigilWroteAndKeepsOtherFiles) {
  TempDir tmp;
  const fs::path mine = tmp.path() / "mine";
  fs::create_directories(mine);
  tmp.File("mine/notes.txt", "mine");
  EXPECT_NE(InputErrorOf([&] { RunToDirectory(kPaper, kTiny, RunOptions{}, mine, false); }), "");
  EXPECT_NE(InputErrorOf([&] {
              RunToDirectory(kPaper, kTiny, RunOptions{}, mine, true);
            }).find("not written by vigil"),
            std::string::npos);
  EXPECT_EQ(ReadFile(mine / "notes.txt"), "mine");
  const fs::path dir = tmp.path() / "run";
  RunToDirectory(kPaper, kTiny, RunOptions{}, dir, false);
  tmp.File("run/notes.txt", "mine");
  EXPECT_NE(InputErrorOf([&] { RunToDirectory(kPaper, kTiny, RunOptions{}, dir, false); }), "");
  RunToDirectory(kPaper, kTiny, RunOptions{}, dir, /*force=*/true);
  EXPECT_EQ(ReadFile(dir / "notes.txt"), "mine");  // not vigil's: kept
  EXPECT_TRUE(fs::exists(dir / "metrics.json"));
}

}  // namespace
}  // namespace vigil::experiments
