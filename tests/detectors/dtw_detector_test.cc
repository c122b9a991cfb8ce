#include "detectors/dtw_detector.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "detectors/detection_metrics.h"
#include "tests/core/test_util.h"
#include "tests/detectors/detector_fixtures.h"

namespace vigil::detectors {
namespace {

// Templates from one synthetic clean run, judged on runs with other seeds (no leakage).
class DtwDetectorTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { library_ = new TemplateLibrary(testing::SyntheticTemplates()); }
  static void TearDownTestSuite() { delete library_; }
  static DetectorOptions Options() { return testing::DetectorOf(DetectorType::kDtw); }
  static TemplateLibrary* library_;
};
TemplateLibrary* DtwDetectorTest::library_ = nullptr;

TEST_F(DtwDetectorTest, FindsLargeGlitchesAndKeepsTheSliceLowFrequencyContent) {
  for (uint64_t seed : {1, 2}) {
    const testing::GlitchedRun run = testing::Glitched(seed, 4001, 50.0, 10.0, 0.01);
    const ImuStream& raw = run.raw;
    const DetectionResult r = DetectAndMitigate(Options(), raw, library_);
    const DetectionMetrics m = EvaluateDetection(raw, r, run.glitches, run.clean);
    EXPECT_GE(m.recall, 0.99) << seed;
    // DTW replaces a whole slice around each spike: right per flagged segment, mostly clean per sample.
    EXPECT_GE(m.segment_f1, 0.9) << seed;
    EXPECT_LT(m.precision, 0.2) << seed;
    EXPECT_LT(m.imu_rmse_cleaned, m.imu_rmse_raw / 5) << seed;
    // The replacement keeps each slice's mean: over replaced slices the mean error stays at noise level.
    double bias = 0.0;
    int replaced = 0;
    for (std::size_t t = 0; t < raw.size(); ++t) {
      if (!r.flagged[t]) continue;
      bias += r.cleaned[t].a_B.z() - run.clean[t].a_B.z();
      ++replaced;
    }
    ASSERT_GT(replaced, 0);
    EXPECT_LT(std::abs(bias / replaced), 0.1) << seed;
  }
}

TEST_F(DtwDetectorTest, RarelyFlagsCleanSlices) {
  const ImuStream clean = testing::SyntheticImu(5, 4001);
  const DetectionResult r = DetectAndMitigate(Options(), clean, library_);
  const DetectionMetrics m = EvaluateDetection(clean, r, {}, clean);
  EXPECT_LE(m.flagged_segments, 2);
}

TEST_F(DtwDetectorTest, StreamsWithOneSliceOfLatencyAndJudgesTheTail) {
  DtwDetector detector({}, *library_);
  EXPECT_EQ(detector.latency_samples(), 39);
  ImuStream imu = testing::SyntheticImu(2, 4001 + 17);
  imu[4010].a_B.z() += 60.0;  // in the incomplete last slice
  const std::vector<DetectedSample> out = testing::StreamThrough(detector, imu);
  ASSERT_EQ(out.size(), imu.size());
  EXPECT_NE(out[4010].flagged_axes, 0);
  EXPECT_LT(std::abs(out[4010].sample.a_B.z() - imu[4009].a_B.z()), 3.0);
}

TEST_F(DtwDetectorTest, AccelerometerOnlyLibraryLeavesTheGyroAlone) {
  DtwOptions options;
  options.dims = 3;
  const TemplateLibrary library = testing::SyntheticTemplates(options);
  ImuStream raw = testing::SyntheticImu(3, 4001);
  raw[100].a_B.z() += 50.0;
  DetectorOptions det = Options();
  const DetectionResult r = DetectAndMitigate(det, raw, &library);
  EXPECT_EQ(r.flagged[100], 1);
  for (int t = 80; t < 120; ++t) EXPECT_EQ(r.cleaned[t].w_B, raw[t].w_B);
}

TEST_F(DtwDetectorTest, RequiresATemplateLibrary) {
  EXPECT_NE(vigil::testing::InputErrorOf([] {
              DetectAndMitigate(Options(), testing::SyntheticImu(1, 100));
            }).find("template library"),
            std::string::npos);
}

}  // namespace
}  // namespace vigil::detectors

namespace vigil::detectors {
namespace {

// Every normalization builds a working library; with none (the paper's raw comparison) the templates must
// also match where the robot is on its trajectory, so it needs the clean data to cover the same motion.
TEST(DtwNormalization, EveryChoiceFindsLargeGlitches) {
  for (const auto& [name, normalization] : SliceNormalizationNames()) {
    DtwOptions options;
    options.normalization = normalization;
    const TemplateLibrary library = testing::SyntheticTemplates(options);
    const DetectionMetrics m = testing::Evaluate(testing::DetectorOf(DetectorType::kDtw),
                                                 testing::Glitched(1, 4001, 50.0, 10.0, 0.01), &library);
    EXPECT_GE(m.recall, 0.95) << name;
    EXPECT_LT(m.imu_rmse_cleaned, m.imu_rmse_raw / 3) << name;
  }
}

}  // namespace
}  // namespace vigil::detectors

namespace vigil::detectors {
namespace {

// One template of 10 rows at rest (a = (0, 0, 9.81)), M = 40, d = 3, threshold 10.
TemplateLibrary RestLibrary(SliceNormalization normalization) {
  TemplateLibrary lib;
  lib.slice_length = 40;
  lib.template_length = 10;
  lib.dims = 3;
  lib.normalization = normalization;
  lib.threshold = 10.0;
  const bool raw = normalization == SliceNormalization::kNone;
  for (int j = 0; j < 10; ++j) lib.values.insert(lib.values.end(), {0.0, 0.0, raw ? 9.81 : 0.0});
  return lib;
}

// One slice at `az`, with a spike of +50 at `spike_at`.
ImuStream Level(double az, int spike_at = -1) {
  std::vector<double> series(40, az);
  if (spike_at >= 0) series[spike_at] += 50.0;
  return testing::AzSeries(series);
}

DetectionResult Clean(const TemplateLibrary& lib, const ImuStream& imu) {
  return DetectAndMitigate(testing::DetectorOf(DetectorType::kDtw), imu, &lib);
}

TEST(DtwRawVsNormalized, RawReplacesAGlitchedSliceByTheBestTemplateItself) {
  const TemplateLibrary raw = RestLibrary(SliceNormalization::kNone);
  const DetectionResult r = Clean(raw, Level(9.81, 20));
  for (int t = 0; t < 40; ++t) {
    EXPECT_EQ(r.flagged[t], 1) << t;  // the whole slice
    EXPECT_DOUBLE_EQ(r.cleaned[t].a_B.z(), 9.81) << t;
  }
}

TEST(DtwRawVsNormalized, ALevelAwayFromEveryTemplateIsAbnormalRawButNormalAfterNormalization) {
  // A real, steady 3 m/s^2 above the templates: raw DTW sees 40 x 3^2 = 360 > 10 and writes the template's
  // level over it; the normalized comparison removes the level and sees a perfect match.
  const DetectionResult raw = Clean(RestLibrary(SliceNormalization::kNone), Level(12.81));
  EXPECT_EQ(raw.flagged[0], 1);
  EXPECT_DOUBLE_EQ(raw.cleaned[5].a_B.z(), 9.81);
  const DetectionResult normalized = Clean(RestLibrary(SliceNormalization::kLinear), Level(12.81));
  EXPECT_EQ(std::count(normalized.flagged.begin(), normalized.flagged.end(), 1), 0);
  EXPECT_DOUBLE_EQ(normalized.cleaned[5].a_B.z(), 12.81);
  // With a spike, the normalized replacement keeps the slice's own level (its robust baseline).
  const DetectionResult spiked = Clean(RestLibrary(SliceNormalization::kLinear), Level(12.81, 20));
  EXPECT_EQ(spiked.flagged[20], 1);
  EXPECT_NEAR(spiked.cleaned[20].a_B.z(), 12.81, 1e-9);
}

}  // namespace
}  // namespace vigil::detectors
