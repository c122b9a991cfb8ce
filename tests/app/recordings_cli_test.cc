// Recordings as input, on the built `vigil`: `vigil inject` (faults with labels on a recording's IMU, images
// linked), detection scored against those labels by `vigil run --dataset`, calibration on a clean reference
// the user names, and why the estimator did not start on the shared real recording.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/output.h"
#include "tests/app/vigil_cli.h"
#include "tests/core/test_util.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::CliResult;
using testing::TempDir;
using testing::Vigil;

const char* kGlitches =
    "--set glitch.enabled=true --set glitch.mean=50 --set glitch.std=10 --set glitch.rate=0.01";

class RecordingsCli : public ::testing::Test {
 protected:
  // A glitch-free 3 s simulation at tmp/clean (imu_clean.csv removed: a recording has none).
  void SetUp() override {
    config_ = tmp_.File("config.yaml", "duration_s: 3\n");
    clean_ = tmp_.path() / "clean";
    ASSERT_EQ(Vigil(tmp_, "simulate " + config_ + " -o " + clean_.string()).status, 0);
    fs::remove(clean_ / "imu_clean.csv");
    fs::remove(clean_ / "glitches.csv");
  }
  void ExpectRefused(const std::string& args, const std::string& reason, const fs::path& not_written) {
    const CliResult r = Vigil(tmp_, args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(not_written)) << not_written;
  }
  nlohmann::json Metrics(const fs::path& run) {
    return nlohmann::json::parse(ReadFile(run / "metrics.json"));
  }

  TempDir tmp_;
  std::string config_;
  fs::path clean_;
};

TEST_F(RecordingsCli, InjectWritesLabelsAndRunScoresAgainstThem) {
  const fs::path injected = tmp_.path() / "injected";
  const CliResult inject =
      Vigil(tmp_, "inject " + clean_.string() + " -o " + injected.string() + " " + kGlitches);
  ASSERT_EQ(inject.status, 0) << inject.err;
  // The recording's own stream is kept as imu_clean.csv, byte for byte; imu.csv differs; labels with kinds.
  EXPECT_EQ(ReadFile(injected / "imu_clean.csv"), ReadFile(clean_ / "imu.csv"));
  EXPECT_NE(ReadFile(injected / "imu.csv"), ReadFile(clean_ / "imu.csv"));
  const std::string glitches = ReadFile(injected / "glitches.csv");
  EXPECT_NE(glitches.find(",offset\n"), std::string::npos) << glitches.substr(0, 200);
  for (const char* file : {"groundtruth.csv", "features.csv", "landmarks.csv", "camera.yaml"})
    EXPECT_EQ(ReadFile(injected / file), ReadFile(clean_ / file)) << file;
  EXPECT_TRUE(fs::exists(injected / ".vigil-output"));
  EXPECT_NE(ReadFile(injected / "injection.yaml").find("rate: 0.01"), std::string::npos);
  // The same keys and seed give the same faults.
  const fs::path again = tmp_.path() / "again";
  ASSERT_EQ(Vigil(tmp_, "inject " + clean_.string() + " -o " + again.string() + " " + kGlitches).status, 0);
  EXPECT_EQ(ReadFile(again / "imu.csv"), ReadFile(injected / "imu.csv"));

  // The paper's threshold calibrates on the injected recording's imu_clean.csv and is scored per sample.
  const fs::path run = tmp_.path() / "run";
  const CliResult r = Vigil(tmp_, "run " + config_ + " --dataset " + injected.string() + " -o " +
                                      run.string() + " --set detector.type=threshold");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("detector threshold (precision "), std::string::npos) << r.err;
  const nlohmann::json detection = Metrics(run)["detection"];
  EXPECT_GT(detection["glitched_samples"].get<int>(), 0);
  EXPECT_GT(detection["recall"].get<double>(), 0.5) << detection.dump();
  EXPECT_GT(detection["precision"].get<double>(), 0.5) << detection.dump();
  EXPECT_NE(detection["threshold_calibration"].get<std::string>().find("imu_clean.csv"), std::string::npos);
}

TEST_F(RecordingsCli, InjectRefusesGlitchesWithoutACleanStream) {
  const fs::path glitched = tmp_.path() / "glitched", out = tmp_.path() / "out";
  ASSERT_EQ(Vigil(tmp_, "simulate " + config_ + " -o " + glitched.string() + " " + kGlitches).status, 0);
  fs::remove(glitched / "imu_clean.csv");
  ExpectRefused("inject " + glitched.string() + " -o " + out.string() + " " + kGlitches,
                "no imu_clean.csv to keep", out);
  ExpectRefused("inject " + clean_.string() + " -o " + out.string() + " --set glitch.rate=2", "glitch.rate",
                out);
  ExpectRefused("inject " + clean_.string() + " -o " + (clean_ / "out").string(), "", clean_ / "out");
}

TEST_F(RecordingsCli, RunOnARecordingNeverCalibratesOnASimulation) {
  const fs::path run = tmp_.path() / "run";
  // No imu_clean.csv and no reference named: refused, as vigil clean refuses.
  ExpectRefused("run " + config_ + " --dataset " + clean_.string() + " -o " + run.string() +
                    " --set detector.type=threshold",
                "detector.threshold.calibration: clean calibrates on glitch-free data", run);
  ExpectRefused(
      "run " + config_ + " --dataset " + clean_.string() + " -o " + run.string() + " --set detector.type=dtw",
      "detector.dtw.templates_file", run);
  // A clean reference named by the user: another flight (seed 2 of the same scenario).
  const fs::path other = tmp_.path() / "other";
  ASSERT_EQ(Vigil(tmp_, "simulate " + config_ + " --seed 2 -o " + other.string()).status, 0);
  const CliResult r =
      Vigil(tmp_, "run " + config_ + " --dataset " + clean_.string() + " -o " + run.string() +
                      " --set detector.type=threshold --set detector.calibration_dataset=" + other.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json detection = Metrics(run)["detection"];
  EXPECT_NE(detection["threshold_calibration"].get<std::string>().find((other / "imu_clean.csv").string()),
            std::string::npos)
      << detection.dump();
  // Nothing is glitched: no label file, so only the flagged fraction (false alarms) is reported.
  EXPECT_LT(detection["flagged_fraction"].get<double>(), 0.01) << detection.dump();
}

TEST_F(RecordingsCli, InjectIntoAEurocFolderLinksTheImages) {
  const fs::path ds = tmp_.path() / "ds", eu = tmp_.path() / "eu", injected = tmp_.path() / "eu_injected";
  const std::string small =
      tmp_.File("small.yaml",
                "duration_s: 1\ncamera: {width: 160, height: 120, fx: 115, fy: 115, cx: 79.5, cy: 59.5}\n");
  ASSERT_EQ(Vigil(tmp_, "simulate " + small + " -o " + ds.string() + " --images").status, 0);
  fs::create_directories(eu);
  fs::copy(ds / "mav0", eu / "mav0", fs::copy_options::recursive);
  fs::copy_file(ds / "features.csv", eu / "features.csv");
  const CliResult r = Vigil(tmp_, "inject " + eu.string() + " -o " + injected.string() + " " + kGlitches +
                                      " --set glitch.rate=0.05 --set faults.timing.drop_rate=0.05");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(injected / "mav0" / "cam0" / "data"));
  EXPECT_EQ(fs::canonical(injected / "mav0" / "cam0" / "data"), fs::canonical(eu / "mav0" / "cam0" / "data"));
  EXPECT_FALSE(fs::is_symlink(injected / "mav0" / "cam0" / "data.csv"));
  EXPECT_NE(ReadFile(injected / "mav0" / "imu0" / "data.csv"), ReadFile(eu / "mav0" / "imu0" / "data.csv"));
  EXPECT_TRUE(fs::exists(injected / "imu_clean.csv"));
  const std::string glitches = ReadFile(injected / "glitches.csv");
  EXPECT_NE(glitches.find(",drop\n"), std::string::npos);
  EXPECT_NE(glitches.find(",offset\n"), std::string::npos);
  // The labels beside mav0/ are read back: vigil clean scores against them.
  const fs::path cleaned = tmp_.path() / "cleaned";
  const CliResult c =
      Vigil(tmp_, "clean " + injected.string() + " -o " + cleaned.string() + " --detector hampel");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.err.find("per sample: precision"), std::string::npos) << c.err;
}

// A recording is its known files: links out of it (to /usr, back into it, a loop) are never followed, and
// an image folder linked elsewhere is an input too, so no output may be written into it.
TEST_F(RecordingsCli, InjectTakesTheRecordingsOwnFilesAndNeverWritesThroughItsLinks) {
  const fs::path ds = tmp_.path() / "ds", eu = tmp_.path() / "eu", images = tmp_.path() / "images";
  const std::string small =
      tmp_.File("small.yaml",
                "duration_s: 1\ncamera: {width: 160, height: 120, fx: 115, fy: 115, cx: 79.5, cy: 59.5}\n");
  ASSERT_EQ(Vigil(tmp_, "simulate " + small + " -o " + ds.string() + " --images").status, 0);
  fs::create_directories(eu);
  fs::copy(ds / "mav0", eu / "mav0", fs::copy_options::recursive);
  fs::rename(eu / "mav0" / "cam0" / "data", images);
  fs::create_directory_symlink(images, eu / "mav0" / "cam0" / "data");
  fs::create_directory_symlink("/usr", eu / "mav0" / "usr_link");
  fs::create_directory_symlink("..", eu / "mav0" / "loop");
  fs::create_directory_symlink(".", eu / "loop");

  for (const std::string command : {"inject", "estimate"})
    ExpectRefused(command + " " + eu.string() + " -o " + (images / "sub").string(),
                  "the output lies inside the input " + (eu / "mav0" / "cam0" / "data").string(),
                  images / "sub");

  const fs::path injected = tmp_.path() / "injected";
  const CliResult r = Vigil(tmp_, "inject " + eu.string() + " -o " + injected.string() + " " + kGlitches);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(
      r.err.find("3 entries that are not part of a recording left out (loop, mav0/loop, mav0/usr_link)"),
      std::string::npos)
      << r.err;
  EXPECT_EQ(fs::canonical(injected / "mav0" / "cam0" / "data"), fs::canonical(images));
  for (const fs::path& absent :
       {injected / "loop", injected / "mav0" / "loop", injected / "mav0" / "usr_link"})
    EXPECT_FALSE(fs::exists(fs::symlink_status(absent))) << absent;
  // The copy holds the recording: every file it lists except the new IMU and labels is the source's.
  EXPECT_EQ(ReadFile(injected / "mav0" / "cam0" / "data.csv"), ReadFile(eu / "mav0" / "cam0" / "data.csv"));
  EXPECT_EQ(ReadFile(injected / "mav0" / "state_groundtruth_estimate0" / "data.csv"),
            ReadFile(eu / "mav0" / "state_groundtruth_estimate0" / "data.csv"));
}

// The shared real recording (../shared/data beside the repository): the MAV stands still for all 95 images.
// Without the static start the visual-inertial initializer never starts and says why; with it (the default)
// the run starts in its first window and holds still.
TEST(SharedEurocCli, RunSaysThePlatformDidNotMove) {
  const fs::path data = fs::path(VIGIL_SOURCE_DIR) / ".." / "shared" / "data" / "euroc_v1_01";
  if (!fs::is_directory(data / "mav0")) GTEST_SKIP() << data << " is absent";
  TempDir tmp;
  const std::string config = std::string(VIGIL_SOURCE_DIR) + "/configs/euroc.yaml --dataset " + data.string();
  const fs::path run = tmp.path() / "run";
  const CliResult r =
      Vigil(tmp, "run " + config + " --set estimator.zero_velocity.static_init=false -o " + run.string());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("the platform did not move"), std::string::npos) << r.err;
  const nlohmann::json m = nlohmann::json::parse(ReadFile(run / "metrics.json"));
  EXPECT_NE(m["failure_reason"].get<std::string>().find("the platform did not move"), std::string::npos);

  const fs::path still = tmp.path() / "still";
  const CliResult s = Vigil(tmp, "run " + config + " -o " + still.string());
  // The shared part of the flight barely moves: its ATE is rightly not computed (min_alignment_extent_m).
  EXPECT_EQ(s.status, 1) << s.err;
  const nlohmann::json ms = nlohmann::json::parse(ReadFile(still / "metrics.json"));
  EXPECT_EQ(ms["status"], "inconclusive") << ms.dump();
  // It starts with its first window: 16 frames solved at 10 Hz.
  EXPECT_LE(ms["estimator"]["initialized_at_s"].get<double>(), 1.55) << ms.dump();
}

}  // namespace
}  // namespace vigil
