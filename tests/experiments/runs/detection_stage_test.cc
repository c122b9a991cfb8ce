#include "experiments/runs/detection_stage.h"

#include <gtest/gtest.h>

#include "core/random.h"
#include "sim/simulator.h"
#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
using testing::InputErrorOf;

RunConfig GlitchyConfig() {
  return LoadRunConfig("", {"duration_s=10", "glitch.enabled=true", "glitch.mean=50", "glitch.std=10",
                            "glitch.rate=0.01", "glitch.axes=[az]"});
}

TEST(DetectionStage, TemplatesComeFromAGlitchFreeSimulationWithAnotherSeed) {
  RunConfig config = GlitchyConfig();
  config.detector.type = detectors::DetectorType::kDtw;
  const auto library = ResolveTemplates(config, nullptr);
  ASSERT_TRUE(library);
  EXPECT_EQ(library->count(), config.detector.dtw.templates);
  EXPECT_GT(library->threshold, 0.0);

  // Exactly the library of the clean IMU of the templates seed; not the run's own clean IMU.
  sim::SimOptions clean = config.sim;
  clean.glitch.enabled = false;
  const Dataset other = sim::Simulate(clean, DeriveSeed(config.seed, "templates"));
  EXPECT_EQ(library->values, detectors::BuildTemplates(other.imu_clean, config.detector.dtw).values);
  const Dataset own = sim::Simulate(config.sim, config.seed);
  EXPECT_NE(library->values, detectors::BuildTemplates(own.imu_clean, config.detector.dtw).values);

  // The glitch settings of the run do not change it.
  RunConfig heavier = config;
  heavier.sim.glitch.mean = 5.0;
  EXPECT_EQ(ResolveTemplates(heavier, nullptr)->values, library->values);
}

TEST(DetectionStage, GivenLibraryIsUsedAndOtherDetectorsNeedNone) {
  RunConfig config = GlitchyConfig();
  EXPECT_EQ(ResolveTemplates(config, nullptr), nullptr);  // detector none
  config.detector.type = detectors::DetectorType::kDtw;
  const detectors::TemplateLibrary given = BuildTemplatesFromGlitchFreeSimulation(config);
  EXPECT_EQ(ResolveTemplates(config, &given).get(), &given);
  config.detector.dtw.templates_file = "/nonexistent/templates.yaml";
  EXPECT_NE(InputErrorOf([&] { ResolveTemplates(config, nullptr); }), "");
}

TEST(DetectionStage, AShortRunStillGetsALibrary) {
  RunConfig config = LoadRunConfig("", {"duration_s=1", "detector.type=dtw"});
  const auto library = ResolveTemplates(config, nullptr);
  ASSERT_TRUE(library);
  EXPECT_EQ(library->count(), config.detector.dtw.templates);
  EXPECT_GE(library->calibration_slices, 2 * (config.detector.dtw.templates + 1));
}

TEST(DetectionStage, ThresholdFindsAndMitigatesLargeGlitches) {
  RunConfig config = GlitchyConfig();
  const Dataset data = sim::Simulate(config.sim, config.seed);
  const DetectionStage none = RunDetection(config, data, nullptr, true, true);
  EXPECT_EQ(none.json["detector"], "none");
  EXPECT_EQ(none.metrics.flagged_samples, 0);
  EXPECT_GT(none.metrics.glitched_samples, 0);
  EXPECT_EQ(none.result.cleaned.size(), data.imu.size());

  config.detector.type = detectors::DetectorType::kThreshold;
  const DetectionStage trunc = RunDetection(config, data, nullptr, true, true);
  EXPECT_EQ(trunc.json["detector"], "threshold");
  EXPECT_GE(trunc.metrics.recall, 0.9);
  // The paper's clamp leaves the distance from the upper bound (about 22 m/s^2) to the true value.
  EXPECT_LT(trunc.metrics.imu_rmse_cleaned, 0.3 * trunc.metrics.imu_rmse_raw);
  EXPECT_EQ(trunc.json["threshold_upper"].size(), 6u);
  EXPECT_NE(trunc.json["threshold_calibration"].get<std::string>().find("calibration"), std::string::npos);
  for (const char* key :
       {"flagged_samples", "glitched_samples", "precision", "recall", "f1", "imu_rmse_vs_clean"})
    EXPECT_TRUE(trunc.json.contains(key)) << key;

  // Without ground truth about the glitches only the flag counts are reported.
  const DetectionStage blind = RunDetection(config, data, nullptr, false, false);
  EXPECT_FALSE(blind.json.contains("recall"));
  EXPECT_FALSE(blind.json.contains("imu_rmse_vs_clean"));
  EXPECT_EQ(blind.metrics.flagged_samples, trunc.metrics.flagged_samples);
}

}  // namespace
}  // namespace vigil::experiments
