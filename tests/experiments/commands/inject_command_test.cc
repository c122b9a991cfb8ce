#include "experiments/commands/inject_command.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "core/dataset.h"
#include "core/output.h"
#include "tests/core/test_util.h"
#include "tests/experiments/commands/command_test_util.h"

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using vigil::testing::InputErrorOf;
using vigil::testing::OnlyEntries;
using vigil::testing::TempDir;
using vigil::testing::WriteSimulatedRecording;

InjectRequest InjectRequestIn(const TempDir& tmp) {
  InjectRequest request;
  request.dataset = (tmp.path() / "rec").string();
  request.output = (tmp.path() / "out").string();
  request.overrides = {"glitch.enabled=true", "glitch.rate=0.05", "glitch.mean=20"};
  return request;
}

TEST(InjectRecording, WritesACopyWithTheFaultyImuItsCleanStreamAndTheLabels) {
  TempDir tmp;
  const Dataset rec = WriteSimulatedRecording(tmp.path() / "rec", 3.0, 4, /*glitches=*/false);
  InjectRequest request = InjectRequestIn(tmp);
  request.seed = "9";
  const InjectResult result = InjectRecording(request);

  EXPECT_EQ(result.imu_samples_in, rec.imu.size());
  EXPECT_EQ(result.imu_samples_out, rec.imu.size());
  ASSERT_FALSE(result.glitches.empty());
  const Dataset out = ReadDataset(request.output);
  EXPECT_EQ(out.glitches.size(), result.glitches.size());
  ASSERT_EQ(out.imu_clean.size(), rec.imu.size());
  // imu_clean.csv is the recording's own IMU; imu.csv differs from it where the faults are.
  for (std::size_t i = 0; i < rec.imu.size(); ++i) EXPECT_EQ(out.imu_clean[i].a_B, rec.imu[i].a_B) << i;
  EXPECT_NE(ReadFile(fs::path(request.output) / "imu.csv"), ReadFile(tmp.path() / "rec" / "imu.csv"));
  // The rest of the recording is copied as it was.
  EXPECT_EQ(ReadFile(fs::path(request.output) / "groundtruth.csv"),
            ReadFile(tmp.path() / "rec" / "groundtruth.csv"));
  const YAML::Node injection = YAML::LoadFile((fs::path(request.output) / "injection.yaml").string());
  EXPECT_EQ(injection["layout"].as<std::string>(), "vigil");
  EXPECT_EQ(injection["injection"]["seed"].as<uint64_t>(), 9u);
  EXPECT_TRUE(injection["injection"]["glitch"]["enabled"].as<bool>());
  const std::string summary = InjectSummary(request, result);
  EXPECT_NE(summary.find(" offset; "), std::string::npos) << summary;
  EXPECT_NE(summary.find("-> " + request.output), std::string::npos) << summary;

  // The same seed gives the same faults; another seed others.
  InjectRequest again = request;
  again.output = (tmp.path() / "again").string();
  InjectRecording(again);
  EXPECT_EQ(ReadFile(fs::path(again.output) / "imu.csv"), ReadFile(fs::path(request.output) / "imu.csv"));
  again.output = (tmp.path() / "other").string();
  again.seed = "10";
  InjectRecording(again);
  EXPECT_NE(ReadFile(fs::path(again.output) / "imu.csv"), ReadFile(fs::path(request.output) / "imu.csv"));
}

TEST(InjectRecording, BadInputIsRefusedBeforeAnythingIsWritten) {
  TempDir tmp;
  WriteSimulatedRecording(tmp.path() / "rec", 2.0, 4, /*glitches=*/false);
  InjectRequest bad_key = InjectRequestIn(tmp);
  bad_key.overrides.push_back("faults.nope=1");
  EXPECT_EQ(InputErrorOf([&] { InjectRecording(bad_key); }), "--set: faults.nope: unknown key");
  InjectRequest missing = InjectRequestIn(tmp);
  missing.dataset = (tmp.path() / "nothere").string();
  EXPECT_EQ(InputErrorOf([&] { InjectRecording(missing); }), missing.dataset + ": not a dataset directory");
  InjectRequest inside = InjectRequestIn(tmp);
  inside.output = (tmp.path() / "rec" / "out").string();
  EXPECT_NE(InputErrorOf([&] { InjectRecording(inside); }).find("the output lies inside the input"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(inside.output));
  // Camera timing faults are the simulator's: inject refuses them instead of ignoring them.
  InjectRequest camera = InjectRequestIn(tmp);
  camera.overrides.push_back("faults.camera.jitter_std_s=0.01");
  EXPECT_EQ(InputErrorOf([&] {
              InjectRecording(camera);
            }).rfind("--set faults.camera.jitter_std_s: inject applies IMU faults only", 0),
            0u);
  // --seed is read as every command reads it, and blamed as --seed.
  for (const char* seed : {"-1", " 1", "1 ", "x", "+1"}) {
    InjectRequest bad_seed = InjectRequestIn(tmp);
    bad_seed.seed = seed;
    EXPECT_EQ(InputErrorOf([&] { InjectRecording(bad_seed); }),
              std::string("--seed: expected an integer from 0 to 9223372036854775807 (2^63 - 1), got '") +
                  seed + "'");
  }
  InjectRequest empty_output = InjectRequestIn(tmp);
  empty_output.output = "";
  EXPECT_EQ(InputErrorOf([&] { InjectRecording(empty_output); }),
            "-o: the output path is empty (name a directory to write)");
  EXPECT_TRUE(OnlyEntries(tmp.path(), {"rec"}));

  // A recording with glitches but without its clean stream: faults on top would lose it.
  WriteSimulatedRecording(tmp.path() / "glitched", 2.0, 4, /*glitches=*/true);
  fs::remove(tmp.path() / "glitched" / "imu_clean.csv");
  InjectRequest glitched = InjectRequestIn(tmp);
  glitched.dataset = (tmp.path() / "glitched").string();
  EXPECT_NE(InputErrorOf([&] {
              InjectRecording(glitched);
            }).find("glitches.csv: the recording already has glitches but no imu_clean.csv"),
            std::string::npos);
  EXPECT_TRUE(OnlyEntries(tmp.path(), {"rec", "glitched"}));
}

}  // namespace
}  // namespace vigil::experiments
