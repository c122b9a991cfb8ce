#include "experiments/commands/clean_command.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

CleanRequest CleanRequestIn(const TempDir& tmp, const std::string& detector) {
  CleanRequest request;
  request.dataset = (tmp.path() / "rec").string();
  request.output = (tmp.path() / "out").string();
  request.detector = detector;
  return request;
}

TEST(CleanRecording, WritesTheCleanedImuFlagsStatisticsAndConfig) {
  TempDir tmp;
  const Dataset rec = WriteSimulatedRecording(tmp.path() / "rec", 4.0, 3, /*glitches=*/true);
  ASSERT_FALSE(rec.glitches.empty());
  CleanRequest request = CleanRequestIn(tmp, "relative_threshold");
  request.overrides = {"detector.relative_threshold.bounds=[5, 5, 5, 5, 5, 5]"};
  const CleanResult result = CleanRecording(request);

  EXPECT_TRUE(result.has_glitches);
  EXPECT_TRUE(result.has_clean);
  EXPECT_EQ(result.metrics.samples, static_cast<int64_t>(rec.imu.size()));
  EXPECT_GT(result.metrics.flagged_samples, 0);
  EXPECT_GT(result.metrics.recall, 0.5);  // 30 m/s^2 glitches against bounds of 5
  // Mitigation brings the IMU closer to the clean stream.
  EXPECT_LT(result.metrics.imu_rmse_cleaned, result.metrics.imu_rmse_raw);

  const fs::path out = request.output;
  EXPECT_EQ(ReadImuCsv((out / "imu.csv").string()).size(), rec.imu.size());
  const nlohmann::json json = nlohmann::json::parse(ReadFile(out / "detection.json"));
  EXPECT_EQ(json.at("detector"), "relative_threshold");
  EXPECT_EQ(json.at("input"), (fs::path(request.dataset) / "imu.csv").string());
  const std::string config = ReadFile(out / "config.yaml");
  EXPECT_EQ(config.rfind("detector:", 0), 0u) << config;
  EXPECT_NE(config.find("type: relative_threshold"), std::string::npos) << config;
  EXPECT_NE(config.find("bounds: [5, 5, 5, 5, 5, 5]"), std::string::npos) << config;
  // One flag row per sample, after a header.
  const std::string flags = ReadFile(out / "detections.csv");
  EXPECT_EQ(static_cast<std::size_t>(std::count(flags.begin(), flags.end(), '\n')), rec.imu.size() + 1);

  EXPECT_NE(CleanSummary(result).find("relative_threshold flagged "), std::string::npos);
  EXPECT_NE(CleanSummary(result).find("; per sample: precision "), std::string::npos);
  EXPECT_NE(CleanSummary(result).find("; IMU RMS vs clean "), std::string::npos);
}

TEST(CleanRecording, WithoutLabelsReportsTheFlaggedShareOnly) {
  TempDir tmp;
  const Dataset rec = WriteSimulatedRecording(tmp.path() / "rec", 2.0, 1, /*glitches=*/false);
  fs::remove(tmp.path() / "rec" / "imu_clean.csv");
  fs::remove(tmp.path() / "rec" / "glitches.csv");
  const CleanResult result = CleanRecording(CleanRequestIn(tmp, "hampel"));
  EXPECT_FALSE(result.has_glitches);
  EXPECT_FALSE(result.has_clean);
  const std::string summary = CleanSummary(result);
  EXPECT_NE(summary.find(" %)"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("precision"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("RMS"), std::string::npos) << summary;
}

TEST(CleanRecording, BadInputIsRefusedBeforeAnythingIsWritten) {
  TempDir tmp;
  WriteSimulatedRecording(tmp.path() / "rec", 2.0, 1, /*glitches=*/true);
  const auto refused = [&](CleanRequest request) {
    const std::string error = InputErrorOf([&] { CleanRecording(request); });
    EXPECT_FALSE(fs::exists(request.output)) << error;
    EXPECT_TRUE(OnlyEntries(tmp.path(), {"rec"})) << error;  // no staging left behind
    return error;
  };
  EXPECT_EQ(refused(CleanRequestIn(tmp, "nope")), "--detector: unknown detector 'nope'");
  CleanRequest bad_key = CleanRequestIn(tmp, "hampel");
  bad_key.overrides = {"detector.nope=1"};
  EXPECT_EQ(refused(bad_key), "--set: detector.nope: unknown key");
  EXPECT_EQ(
      refused(CleanRequestIn(tmp, "threshold")).rfind("detector.threshold.calibration: clean calibrates", 0),
      0u);
  EXPECT_EQ(
      refused(CleanRequestIn(tmp, "dtw")).rfind("--templates: the dtw detector needs a template library", 0),
      0u);
  CleanRequest inside = CleanRequestIn(tmp, "hampel");
  inside.output = (tmp.path() / "rec" / "out").string();
  EXPECT_NE(InputErrorOf([&] { CleanRecording(inside); }).find("the output lies inside the input"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(inside.output));
  // A broken IMU file: named with its line.
  tmp.File("rec/imu.csv", "#timestamp [ns],w_x,w_y,w_z,a_x,a_y,a_z\n1000,0,0,0,0,0,x\n");
  const std::string broken = refused(CleanRequestIn(tmp, "hampel"));
  EXPECT_NE(broken.find("imu.csv:2"), std::string::npos) << broken;
}

}  // namespace
}  // namespace vigil::experiments
