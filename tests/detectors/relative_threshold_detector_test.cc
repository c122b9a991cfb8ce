#include "detectors/relative_threshold_detector.h"

#include <gtest/gtest.h>

#include "detectors/detection_metrics.h"
#include "tests/core/test_util.h"
#include "tests/detectors/detector_fixtures.h"

namespace vigil::detectors {
namespace {

using testing::DetectorOf;

ImuStream Constant(int samples, double az) { return testing::AzSeries(std::vector<double>(samples, az)); }

TEST(RelativeThresholdDetector, TruncatesASpikeToReferencePlusBound) {
  ImuStream imu = Constant(20, 9.81);
  imu[10].a_B.z() += 50.0;
  RelativeThresholdOptions options;  // az bound 2.5
  const DetectionResult r = DetectAndMitigate(DetectorOf(options), imu);
  for (int t = 0; t < 20; ++t) EXPECT_EQ(r.flagged[t], t == 10 ? 1 : 0) << t;
  EXPECT_DOUBLE_EQ(r.cleaned[10].a_B.z(), 9.81 + options.bounds[5]);
  EXPECT_DOUBLE_EQ(r.cleaned[11].a_B.z(), 9.81);
  EXPECT_EQ(r.cleaned[10].t_ns, imu[10].t_ns);
}

TEST(RelativeThresholdDetector, MeanMitigationWritesTheMeanOfTheLastNormalValues) {
  ImuStream imu = Constant(10, 0.0);
  for (int t = 0; t < 10; ++t) imu[t].a_B.x() = 0.1 * t;  // a slow ramp: normal
  imu[6].a_B.x() = -40.0;
  RelativeThresholdOptions options;
  options.mitigation = ThresholdMitigation::kMean;
  options.reference_samples = 3;
  const DetectionResult r = DetectAndMitigate(DetectorOf(options), imu);
  EXPECT_EQ(r.flagged[6], 1);
  EXPECT_NEAR(r.cleaned[6].a_B.x(), (0.3 + 0.4 + 0.5) / 3, 1e-12);
  EXPECT_EQ(r.flagged[7], 0);  // the spike did not enter the reference
}

TEST(RelativeThresholdDetector, AcceptsAPersistentNewLevelAfterMaxRun) {
  ImuStream imu = Constant(30, 0.0);
  for (int t = 10; t < 30; ++t) imu[t].a_B.z() = 20.0;  // a real step in the motion
  RelativeThresholdOptions options;
  options.max_run = 4;
  const DetectionResult r = DetectAndMitigate(DetectorOf(options), imu);
  for (int t = 10; t < 13; ++t) EXPECT_EQ(r.flagged[t], 1) << t;
  for (int t = 13; t < 30; ++t) EXPECT_EQ(r.flagged[t], 0) << t;
  EXPECT_DOUBLE_EQ(r.cleaned[20].a_B.z(), 20.0);
}

TEST(RelativeThresholdDetector, CalibratedBoundsFlagNothingOnTheirCleanDataAndCatchLargeGlitches) {
  const ImuStream clean = testing::SyntheticImu(1000, 4000);
  RelativeThresholdOptions options;
  options.bounds = CalibrateRelativeThresholdBounds(clean, options);
  for (double b : options.bounds) EXPECT_GT(b, 0.0);
  const DetectorOptions det = DetectorOf(options);
  const DetectionResult on_clean = DetectAndMitigate(det, clean);
  EXPECT_EQ(std::count(on_clean.flagged.begin(), on_clean.flagged.end(), 1), 0);

  const DetectionMetrics m = testing::Evaluate(det, testing::Glitched(1, 4000, 50.0, 10.0, 0.01));
  EXPECT_GE(m.recall, 0.99);
  EXPECT_GE(m.f1, 0.9);
  EXPECT_LT(m.imu_rmse_cleaned, m.imu_rmse_raw / 5);
}

TEST(RelativeThresholdDetector, RejectsBadBounds) {
  RelativeThresholdOptions options;
  options.bounds = {1.0, 2.0};
  EXPECT_NE(vigil::testing::InputErrorOf([&] {
              RelativeThresholdDetector d(options);
            }).find("detector.relative_threshold.bounds"),
            std::string::npos);
  options.bounds = {1, 1, 1, 1, 1, 0};
  EXPECT_THROW(RelativeThresholdDetector{options}, InputError);
}

}  // namespace
}  // namespace vigil::detectors
