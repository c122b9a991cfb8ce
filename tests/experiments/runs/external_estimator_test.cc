// The external path of a run (estimator.backend: external), driven by a fake estimator executable
// (fake_estimator.cc) that succeeds or fails in one way per mode.
#include "experiments/runs/external_estimator.h"

#include <chrono>

#include <gtest/gtest.h>

#include "core/euroc.h"
#include "core/output.h"
#include "experiments/commands/run_command.h"
#include "experiments/external/external_command.h"
#include "experiments/runs/run_metrics.h"
#include "experiments/sweeps/sweep_runner.h"
#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

const std::string kPaper = std::string(VIGIL_SOURCE_DIR) + "/configs/paper.yaml";

std::vector<std::string> ExternalOverrides(const std::string& mode,
                                           const std::vector<std::string>& more = {}) {
  std::vector<std::string> o = {"duration_s=2", "estimator.backend=external",
                                "estimator.external.command=[" + std::string(VIGIL_FAKE_ESTIMATOR) + ", " +
                                    mode + ", \"{output}\", \"{recording}\"]"};
  o.insert(o.end(), more.begin(), more.end());
  return o;
}

nlohmann::json RunFake(const TempDir& tmp, const std::string& mode,
                       const std::vector<std::string>& more = {}) {
  return RunToDirectory(kPaper, ExternalOverrides(mode, more), RunOptions{}, tmp.path() / "run", false);
}

std::string Reason(const nlohmann::json& metrics) { return metrics.at("failure_reason").get<std::string>(); }

TEST(ExternalEstimator, AGoodTrajectoryIsEvaluatedLikeVigilsOwn) {
  TempDir tmp;
  const nlohmann::json m = RunFake(tmp, "good");
  ASSERT_EQ(m["status"], "ok") << Reason(m);
  EXPECT_LT(m["ate"]["trans_m"]["rmse"].get<double>(), 1e-6);  // the fake writes the ground truth
  EXPECT_GT(m["coverage"].get<double>(), 0.99);
  EXPECT_EQ(m["external"]["outcome"], "exited");
  EXPECT_EQ(m["external"]["rows"], 61);  // 2 s at 30 Hz
  for (const char* key : {"write_recording", "process", "read"})
    EXPECT_GE(m["external"]["wall_time_s"][key].get<double>(), 0.0) << key;
  const fs::path run = tmp.path() / "run";
  EXPECT_EQ(ReadFile(run / "external/stdout.txt"), "fake estimator: good\n");
  EXPECT_TRUE(fs::is_regular_file(run / "external/output/stamped_traj_estimate.txt"));
  EXPECT_TRUE(fs::is_regular_file(run / "stamped_traj_estimate.txt"));
  EXPECT_FALSE(fs::exists(run / "external/recording"));  // a temporary folder, removed
}

TEST(ExternalEstimator, TheRecordingIsEurocWithTheRunsNoise) {
  TempDir tmp;
  const nlohmann::json m =
      RunFake(tmp, "good", {"estimator.external.keep_recording=true", "imu.noise.gyro_noise_density=0.0123"});
  ASSERT_EQ(m["status"], "ok") << Reason(m);
  const fs::path rec = tmp.path() / "run/external/recording";
  for (const char* f :
       {"mav0/imu0/data.csv", "mav0/imu0/sensor.yaml", "mav0/cam0/data.csv", "mav0/cam0/sensor.yaml",
        "mav0/state_groundtruth_estimate0/data.csv", "features.csv", "config.yaml"})
    EXPECT_TRUE(fs::is_regular_file(rec / f)) << f;
  const Recording r = ReadRecording(rec, false);
  EXPECT_EQ(r.imu_sensor.gyroscope_noise_density, 0.0123);
  EXPECT_EQ(r.images.size(), 61u);
  EXPECT_TRUE(r.has_features);
}

TEST(ExternalEstimator, ADatasetRunsRecordingCarriesTheDatasetsOwnImuSensor) {
  // A EuRoC folder whose imu0/sensor.yaml says 200 Hz and 0.0123: the kept recording of a first run, with a
  // file for each frame's image (a dataset run with images links them into its recording).
  TempDir tmp;
  ASSERT_EQ(
      RunFake(tmp, "good", {"estimator.external.keep_recording=true", "imu.noise.gyro_noise_density=0.0123"})
          .at("status"),
      "ok");
  const fs::path dataset = tmp.path() / "run/external/recording";
  fs::create_directories(dataset / "mav0/cam0/data");
  for (const CameraImage& image : ReadRecording(dataset, false).images) WriteFileAtomic(image.path, "");
  // The second run configures another rate and noise; the estimator is told the dataset's.
  RunOptions from_dataset;
  from_dataset.dataset_dir = dataset;
  const nlohmann::json m =
      RunToDirectory(kPaper,
                     ExternalOverrides("good", {"estimator.external.keep_recording=true", "imu.rate_hz=400",
                                                "imu.noise.gyro_noise_density=0.5"}),
                     from_dataset, tmp.path() / "run2", false);
  ASSERT_EQ(m["status"], "ok") << Reason(m);
  const Recording r = ReadRecording(tmp.path() / "run2/external/recording", false);
  EXPECT_EQ(r.imu_sensor.gyroscope_noise_density, 0.0123);
  EXPECT_EQ(r.imu_sensor.rate_hz, 200.0);
  EXPECT_EQ(r.images.size(), 61u);
}

TEST(ExternalEstimator, PartialCoverageIsEvaluatedOnWhatItCovers) {
  TempDir tmp;
  const nlohmann::json m = RunFake(tmp, "partial");
  ASSERT_EQ(m["status"], "ok") << Reason(m);
  EXPECT_GT(m["coverage"].get<double>(), 0.4);
  EXPECT_LT(m["coverage"].get<double>(), 0.6);
  EXPECT_LT(m["ate"]["trans_m"]["rmse"].get<double>(), 1e-6);
}

// Two poses of 61 frames cover almost nothing: inconclusive, not ok, whatever their ATE.
TEST(ExternalEstimator, ATrajectoryOfTwoPosesIsInconclusive) {
  TempDir tmp;
  const nlohmann::json m = RunFake(tmp, "two");
  EXPECT_EQ(m["status"], "inconclusive");
  EXPECT_NE(Reason(m).find("coverage 3.3 % (2 of 61 ground-truth poses) is below evaluation.min_coverage"),
            std::string::npos)
      << Reason(m);
}

// metrics.json of an external run names what exists after the run and says which estimator ran.
TEST(ExternalEstimator, MetricsDescribeTheExternalRun) {
  TempDir tmp;
  const nlohmann::json m = RunFake(tmp, "good");
  ASSERT_EQ(m["status"], "ok") << Reason(m);
  EXPECT_EQ(m["estimator"]["backend"], "external");
  EXPECT_EQ(m["estimator"]["init"], "external");
  EXPECT_TRUE(m["estimator"]["keyframes"].is_null());
  EXPECT_TRUE(m["estimator"]["resets"].is_null());
  EXPECT_EQ(m["estimator"]["output_poses"], 61);
  const nlohmann::json& command = m["external"]["command"];
  ASSERT_EQ(command.size(), 4u);
  EXPECT_EQ(command[2], (fs::absolute(tmp.path()) / "run/external/output").lexically_normal().string());
  EXPECT_TRUE(fs::is_directory(command[2].get<std::string>()));
  EXPECT_NE(m["external"]["recording"].get<std::string>().find("removed after the run"), std::string::npos);
  EXPECT_EQ(RunSummaryLine(m).find("marginalization"), std::string::npos);
}

TEST(ExternalEstimator, EurocNanoseconds) {
  TempDir tmp;
  const nlohmann::json m = RunFake(tmp, "euroc_ns",
                                   {"estimator.external.format=euroc", "estimator.external.time_unit=ns",
                                    "estimator.external.trajectory=traj.csv"});
  ASSERT_EQ(m["status"], "ok") << Reason(m);
  EXPECT_GT(m["coverage"].get<double>(), 0.99);
}

TEST(ExternalEstimator, EveryFailureIsAFailedRunWithItsReason) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"exit3", "exit status 3"},
      {"signal", "killed by signal 9"},
      {"garbage", "columns, expected the TUM"},
      {"ns", "outside the recording"},
      {"unsorted", "not strictly increasing"},
      {"scaled_q", "quaternion is not unit (norm 3)"},
      {"nan", "not a finite number"},
      {"empty", "the trajectory is empty"},
      {"none", "wrote no trajectory"},
  };
  for (const auto& [mode, expected] : cases) {
    TempDir tmp;
    const nlohmann::json m = RunFake(tmp, mode);
    EXPECT_EQ(m["status"], "failed") << mode;
    EXPECT_NE(Reason(m).find("external estimator: "), std::string::npos) << Reason(m);
    EXPECT_NE(Reason(m).find(expected), std::string::npos) << mode << ": " << Reason(m);
    EXPECT_TRUE(fs::is_regular_file(tmp.path() / "run/metrics.json")) << mode;
  }
}

// The trajectory is what the estimator wrote into {output}: a link out of it (to /etc/passwd, or here to a
// good trajectory beside it) is not followed; a link to a file inside it is.
TEST(ExternalEstimator, ATrajectoryLinkOutOfTheOutputFolderIsNotRead) {
  TempDir tmp;
  const nlohmann::json out = RunFake(tmp, "link_out");
  EXPECT_EQ(out["status"], "failed");
  EXPECT_EQ(Reason(out).rfind("external estimator: stamped_traj_estimate.txt: resolves to ", 0), 0u)
      << Reason(out);
  EXPECT_NE(Reason(out).find("/external/outside.txt, outside the estimator's {output} folder: not read"),
            std::string::npos)
      << Reason(out);
  TempDir other;
  const nlohmann::json in = RunFake(other, "link_in");
  EXPECT_EQ(in["status"], "ok") << Reason(in);
}

// Seconds read as nanoseconds collapse onto a few ns: named a unit mix-up although the simulated recording
// starts at t = 0, where every such time lies inside it.
TEST(ExternalEstimator, SecondsReadAsNanosecondsAreAUnitMixUp) {
  TempDir tmp;
  const nlohmann::json m = RunFake(tmp, "good", {"estimator.external.time_unit=ns"});
  EXPECT_EQ(m["status"], "failed");
  EXPECT_NE(Reason(m).find("a unit mix-up? (estimator.external.time_unit ns reads them as nanoseconds)"),
            std::string::npos)
      << Reason(m);
}

TEST(ExternalEstimator, TimeoutKillsItAndFailsTheRun) {
  TempDir tmp;
  const auto start = std::chrono::steady_clock::now();
  const nlohmann::json m = RunFake(tmp, "sleep", {"estimator.external.timeout_s=0.5"});
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
  EXPECT_EQ(m["status"], "failed");
  EXPECT_NE(Reason(m).find("timed out after 0.5 s"), std::string::npos) << Reason(m);
  EXPECT_EQ(m["external"]["outcome"], "timed_out");
}

TEST(ExternalEstimator, BadOptionsAreInputErrorsNamingFileLineAndKey) {
  TempDir tmp;
  const auto error_of = [&](const std::string& external) {
    const std::string path =
        tmp.File("c.yaml", "duration_s: 2\nestimator:\n  backend: external\n  external:\n" + external);
    return InputErrorOf([&] { LoadRunConfig(path); });
  };
  const std::string file = (tmp.path() / "c.yaml").string();
  std::string e = error_of("    command: [/no/such/estimator, x]\n");
  EXPECT_EQ(e.rfind(file + ":5: estimator.external.command: ", 0), 0u) << e;
  EXPECT_NE(e.find("not an executable file"), std::string::npos) << e;
  e = error_of("    command: [\"" + std::string(VIGIL_SOURCE_DIR) +
               "/README.md\"]\n");  // a file, not executable
  EXPECT_NE(e.find("not an executable file"), std::string::npos) << e;
  e = error_of("    command: [" + std::string(VIGIL_FAKE_ESTIMATOR) + ", \"{recordings}\"]\n");
  EXPECT_EQ(e.rfind(file + ":5: estimator.external.command: ", 0), 0u) << e;
  EXPECT_NE(e.find("unknown placeholder {recordings}"), std::string::npos) << e;
  e = error_of("    command: [" + std::string(VIGIL_FAKE_ESTIMATOR) + "]\n    format: xml\n");
  EXPECT_EQ(e.rfind(file + ":6: estimator.external.format: ", 0), 0u) << e;
  e = error_of("    command: [" + std::string(VIGIL_FAKE_ESTIMATOR) + "]\n    timeout_s: 0\n");
  EXPECT_EQ(e.rfind(file + ":6: estimator.external.timeout_s: ", 0), 0u) << e;
  e = error_of("    command: [" + std::string(VIGIL_FAKE_ESTIMATOR) + "]\n    trajectory: ../x.txt\n");
  EXPECT_NE(e.find("estimator.external.trajectory: "), std::string::npos) << e;
  for (const char* folder : {".", "traj.txt/"}) {
    e = error_of("    command: [" + std::string(VIGIL_FAKE_ESTIMATOR) + "]\n    trajectory: \"" + folder +
                 "\"\n");
    EXPECT_EQ(e.rfind(file + ":6: estimator.external.trajectory: '" + folder + "' names a folder", 0), 0u)
        << e;
  }
  e = error_of("    trajectory: x.txt\n");
  EXPECT_NE(e.find("estimator.external.command: backend external needs a command"), std::string::npos) << e;
  // --set: the override is named.
  e = InputErrorOf([&] {
    LoadRunConfig("", {"estimator.backend=external", "estimator.external.command=[nope_nope]"});
  });
  EXPECT_EQ(e.rfind("--set estimator.external.command=[nope_nope]: ", 0), 0u) << e;
}

TEST(ExternalEstimator, ASweepMethodNeedingImagesIsRefusedBeforeAnythingIsWritten) {
  TempDir tmp;
  tmp.File("base.yaml", "seed: 1\nduration_s: 2\n");
  const std::string sweep =
      tmp.File("sweep.yaml",
               "base: base.yaml\nmethods:\n  none: none\n  ext:\n    type: none\n"
               "    estimator.backend: external\n    estimator.external:\n      command: [" +
                   std::string(VIGIL_FAKE_ESTIMATOR) +
                   ", good, \"{output}\", \"{recording}\"]\n      input: images\nseeds: [1]\n");
  const SweepSpec spec = LoadSweepSpec(sweep);
  const std::string e = InputErrorOf([&] { ResolveSweepPlan(spec); });
  EXPECT_EQ(e.rfind(sweep + ":", 0), 0u) << e;
  EXPECT_NE(e.find("estimator.external.input: images: the recording has no camera images"), std::string::npos)
      << e;
}

TEST(ExternalEstimator, APlaceholderIsExpandedAndBracesEscaped) {
  const CommandPlaceholders v{"/r", "/r/mav0", "/o", "/r/config.yaml", "7", "/bin/vigil"};
  EXPECT_EQ(ExpandPlaceholders("--out={output}/x", v), "--out=/o/x");
  EXPECT_EQ(ExpandPlaceholders("{vigil}", v), "/bin/vigil");
  EXPECT_EQ(ExpandPlaceholders("{{seed}}={seed}", v), "{seed}=7");
  EXPECT_NE(InputErrorOf([&] { ExpandPlaceholders("{outptu}", v); }).find("unknown placeholder {outptu}"),
            std::string::npos);
  EXPECT_NE(InputErrorOf([&] { ExpandPlaceholders("{output", v); }).find("unmatched '{'"), std::string::npos);
}

}  // namespace
}  // namespace vigil::experiments
