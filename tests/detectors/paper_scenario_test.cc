// The detectors on the paper's simulation scenario (ellipse, 20 s, IMU 200 Hz, glitches on acc z at rate
// 0.01): templates from a glitch-free run with seed 1000, judged on runs with other seeds.
#include <string>

#include <gtest/gtest.h>

#include "detectors/detection_metrics.h"
#include "detectors/detector.h"
#include "detectors/template_library.h"
#include "sim/simulator.h"
#include "tests/detectors/detector_fixtures.h"

namespace vigil::detectors {
namespace {

sim::SimOptions Scenario(bool glitches, double mean, double std) {
  sim::SimOptions options;  // the defaults are the paper's scenario
  options.glitch.enabled = glitches;
  options.glitch.mean = mean;
  options.glitch.std = std;
  options.glitch.rate = 0.01;
  options.glitch.axes = {ImuAxis::kAz};
  return options;
}

class PaperScenario : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    library_ = new TemplateLibrary(
        BuildTemplates(sim::Simulate(Scenario(false, 0, 1), 1000).imu_clean, testing::NormalizedDtw()));
  }
  static void TearDownTestSuite() { delete library_; }
  static DetectionMetrics Run(DetectorType type, const Dataset& data) {
    const DetectorOptions options = testing::DetectorOf(type);
    return EvaluateDetection(data.imu, DetectAndMitigate(options, data.imu, library_), data.glitches,
                             data.imu_clean);
  }
  static TemplateLibrary* library_;
};
TemplateLibrary* PaperScenario::library_ = nullptr;

TEST_F(PaperScenario, LargeGlitchesAreFoundAndMitigated) {
  for (uint64_t seed : {1, 2}) {
    const Dataset data = sim::Simulate(Scenario(true, 50, 10), seed);
    ASSERT_GT(data.glitches.size(), 10u);
    const DetectionMetrics threshold = Run(DetectorType::kRelativeThreshold, data);
    const DetectionMetrics dtw = Run(DetectorType::kDtw, data);
    const DetectionMetrics hampel = Run(DetectorType::kHampel, data);
    EXPECT_GE(threshold.f1, 0.9) << seed;
    EXPECT_GE(dtw.segment_f1, 0.9) << seed;  // DTW flags whole slices: scored per segment
    EXPECT_LT(threshold.imu_rmse_cleaned, threshold.imu_rmse_raw / 5) << seed;
    for (const DetectionMetrics& m : {threshold, dtw, hampel}) {
      EXPECT_GE(m.recall, 0.95) << seed;
      EXPECT_LT(m.imu_rmse_cleaned, m.imu_rmse_raw / 3) << seed;
    }
  }
}

TEST_F(PaperScenario, GlitchesInsideTheNoiseRaiseFewFalseAlarms) {
  const Dataset data = sim::Simulate(Scenario(true, 0, 1), 3);
  const DetectionMetrics threshold = Run(DetectorType::kRelativeThreshold, data);
  const DetectionMetrics dtw = Run(DetectorType::kDtw, data);
  const DetectionMetrics hampel = Run(DetectorType::kHampel, data);
  EXPECT_LT(threshold.false_positive_rate, 0.005);
  EXPECT_LE(dtw.flagged_segments, 3);  // a few 40-sample slices at most
  EXPECT_LT(hampel.false_positive_rate, 0.01);
  // Nothing here is worth mitigating: the output stays about as close to the clean IMU as the input. (Each
  // Hampel false alarm is a noise extreme replaced by the median, an error of the size of that noise: with
  // ~0.5 % false alarms against 1 % tiny glitches its output moves a little further from the clean IMU.)
  EXPECT_LT(threshold.imu_rmse_cleaned, 1.05 * threshold.imu_rmse_raw);
  EXPECT_LT(dtw.imu_rmse_cleaned, 1.2 * dtw.imu_rmse_raw) << dtw.flagged_samples << " flagged";
  EXPECT_LT(hampel.imu_rmse_cleaned, 1.5 * hampel.imu_rmse_raw) << hampel.flagged_samples << " flagged";
}

TEST_F(PaperScenario, CleanRunsOfOtherSeedsAreRarelyFlagged) {
  const Dataset data = sim::Simulate(Scenario(false, 0, 1), 4);
  EXPECT_LE(Run(DetectorType::kDtw, data).flagged_segments, 2);
  EXPECT_EQ(Run(DetectorType::kRelativeThreshold, data).flagged_samples, 0);
}

}  // namespace
}  // namespace vigil::detectors

namespace vigil::detectors {
namespace {

// The rescue course (a ground robot over a ramp, a platform and bumps): its bumps are real motion, not
// glitches.
sim::SimOptions RescueCourse(bool glitches) {
  sim::SimOptions options = Scenario(glitches, 50, 10);
  options.trajectory.type = sim::TrajectoryType::kRescue;
  options.duration_s = 36;
  options.landmarks.layout = sim::LandmarkLayout::kRandom;
  options.landmarks.random_count = 300;
  return options;
}

TEST(RescueCourse, LegitimateBumpsRaiseFewFalseAlarmsAndGlitchesAreStillFound) {
  const Dataset templates_run = sim::Simulate(RescueCourse(false), 1000);
  const TemplateLibrary library = BuildTemplates(templates_run.imu_clean, testing::NormalizedDtw());
  const Dataset clean = sim::Simulate(RescueCourse(false), 1),
                glitched = sim::Simulate(RescueCourse(true), 1);
  for (DetectorType type : {DetectorType::kRelativeThreshold, DetectorType::kDtw, DetectorType::kHampel}) {
    const DetectorOptions options = testing::DetectorOf(type);
    const DetectionMetrics on_clean =
        EvaluateDetection(clean.imu, DetectAndMitigate(options, clean.imu, &library), {}, clean.imu_clean);
    EXPECT_LT(on_clean.false_positive_rate, type == DetectorType::kDtw ? 0.03 : 0.01)
        << static_cast<int>(type);
    const DetectionMetrics on_glitches =
        EvaluateDetection(glitched.imu, DetectAndMitigate(options, glitched.imu, &library), glitched.glitches,
                          glitched.imu_clean);
    EXPECT_GE(on_glitches.recall, 0.95) << static_cast<int>(type);
    EXPECT_LT(on_glitches.imu_rmse_cleaned, on_glitches.imu_rmse_raw / 3) << static_cast<int>(type);
    if (type != DetectorType::kHampel) {
      // DTW flags whole slices: scored per segment.
      const double f1 = type == DetectorType::kDtw ? on_glitches.segment_f1 : on_glitches.f1;
      EXPECT_GE(f1, 0.9) << static_cast<int>(type);
    }
  }
}

}  // namespace
}  // namespace vigil::detectors
