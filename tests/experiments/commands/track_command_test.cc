#include "experiments/commands/track_command.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "core/dataset.h"
#include "core/output.h"
#include "sim/simulator.h"
#include "tests/core/test_util.h"
#include "tests/experiments/commands/command_test_util.h"

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using vigil::testing::InputErrorOf;
using vigil::testing::OnlyEntries;
using vigil::testing::TempDir;
using vigil::testing::WriteSimulatedRecording;

TEST(TrackToDirectory, TracksRenderedImagesAndEvaluatesThemAgainstTheScene) {
  TempDir tmp;
  sim::SimOptions options;
  options.duration_s = 1.0;
  options.images.enabled = true;
  options.images.antialias_samples = 0;
  options.images.texture_size_px = 128;
  const Dataset dataset = sim::Simulate(options, 5);
  const fs::path rec = tmp.path() / "rec";
  fs::create_directories(rec);
  WriteDataset(rec, dataset);
  sim::WriteImages(options, 5, dataset, rec);

  TrackRequest request;
  request.dataset = rec.string();
  request.output = (tmp.path() / "out").string();
  request.overrides = {"frontend.evaluation.outlier_threshold_px=3"};
  const TrackResult result = TrackToDirectory(request);

  EXPECT_EQ(result.frontend.at("images").get<std::size_t>(), dataset.frames.size());
  EXPECT_GT(result.frontend.at("tracks").get<int64_t>(), 0);
  ASSERT_TRUE(result.outlier_ratio);  // ground truth and scene.obj: the tracks are evaluated
  EXPECT_LT(*result.outlier_ratio, 0.5);
  EXPECT_EQ(result.outlier_threshold_px, 3.0);
  EXPECT_EQ(result.frontend.at("dataset"), fs::absolute(rec).lexically_normal().string());
  EXPECT_EQ(nlohmann::json::parse(ReadFile(fs::path(request.output) / "frontend.json")), result.frontend);
  EXPECT_NE(ReadFile(fs::path(request.output) / "features.csv").find('\n'), std::string::npos);
  const std::string config = ReadFile(fs::path(request.output) / "config.yaml");
  EXPECT_EQ(config.rfind("frontend:", 0), 0u) << config;
  EXPECT_NE(config.find("outlier_threshold_px: 3"), std::string::npos) << config;
  const std::string summary = TrackSummary(request, result);
  EXPECT_NE(summary.find("reprojection error median"), std::string::npos) << summary;
  EXPECT_NE(summary.find("above 3 px"), std::string::npos) << summary;
}

TEST(TrackToDirectory, BadInputIsRefusedBeforeAnythingIsWritten) {
  TempDir tmp;
  WriteSimulatedRecording(tmp.path() / "rec", 1.0, 1, /*glitches=*/false);
  TrackRequest request;
  request.dataset = (tmp.path() / "rec").string();
  request.output = (tmp.path() / "out").string();
  EXPECT_EQ(InputErrorOf([&] { TrackToDirectory(request); }),
            request.dataset + ": no camera images (expected mav0/cam0/data.csv and sensor.yaml)");
  request.overrides = {"frontend.evaluation.outlier_threshold_px=-1"};
  EXPECT_EQ(InputErrorOf([&] { TrackToDirectory(request); }),
            "--set: frontend.evaluation.outlier_threshold_px: must be > 0");
  request.overrides = {"frontend.nope=2"};
  EXPECT_EQ(InputErrorOf([&] { TrackToDirectory(request); }), "--set: frontend.nope: unknown key");
  EXPECT_TRUE(OnlyEntries(tmp.path(), {"rec"}));
}

}  // namespace
}  // namespace vigil::experiments
