#include "detectors/threshold_detector.h"

#include <gtest/gtest.h>

#include "detectors/detection_metrics.h"
#include "tests/core/test_util.h"
#include "tests/detectors/detector_fixtures.h"

namespace vigil::detectors {
namespace {

using testing::AzSeries;
using testing::DetectorOf;

// az bounds [-2, 24]; every other axis +-1.
ThresholdOptions PaperBounds() {
  ThresholdOptions o;
  o.calibration = ThresholdCalibration::kManual;
  o.lower = {-1, -1, -1, -1, -1, -2};
  o.upper = {1, 1, 1, 1, 1, 24};
  return o;
}

TEST(ThresholdDetector, AValueJustInsideABoundIsNormalJustOutsideIsClampedToThatBound) {
  const ImuStream imu = AzSeries({9.81, 24.0, 24.0 + 1e-9, -2.0, -2.0 - 1e-9, 70.0, -30.0, 9.81});
  const DetectionResult r = DetectAndMitigate(DetectorOf(PaperBounds()), imu);
  const std::vector<uint8_t> expected = {0, 0, 1, 0, 1, 1, 1, 0};
  EXPECT_EQ(r.flagged, expected);
  EXPECT_DOUBLE_EQ(r.cleaned[1].a_B.z(), 24.0);
  EXPECT_DOUBLE_EQ(r.cleaned[2].a_B.z(), 24.0);  // the upper bound
  EXPECT_DOUBLE_EQ(r.cleaned[4].a_B.z(), -2.0);  // the lower bound
  EXPECT_DOUBLE_EQ(r.cleaned[5].a_B.z(), 24.0);
  EXPECT_DOUBLE_EQ(r.cleaned[6].a_B.z(), -2.0);
  EXPECT_DOUBLE_EQ(r.cleaned[7].a_B.z(), 9.81);
  EXPECT_EQ(r.cleaned[5].t_ns, imu[5].t_ns);
}

TEST(ThresholdDetector, BoundsAreOnTheValueNotOnTheChange) {
  // A large but in-range jump (a robot starting to move) passes; the relative rule would flag it.
  const ImuStream imu = AzSeries({0.0, 0.0, 20.0, 20.0});
  const DetectionResult r = DetectAndMitigate(DetectorOf(PaperBounds()), imu);
  EXPECT_EQ(std::count(r.flagged.begin(), r.flagged.end(), 1), 0);
}

TEST(ThresholdDetector, MeanMitigationWritesTheMeanOfTheLastOutputValues) {
  ThresholdOptions o = PaperBounds();
  o.mitigation = ThresholdMitigation::kMean;
  o.mean_samples = 3;
  const ImuStream imu = AzSeries({1.0, 2.0, 3.0, 4.0, 60.0, 60.0, 5.0});
  const DetectionResult r = DetectAndMitigate(DetectorOf(o), imu);
  EXPECT_EQ(r.flagged[4], 1);
  EXPECT_DOUBLE_EQ(r.cleaned[4].a_B.z(), (2.0 + 3.0 + 4.0) / 3);
  // The next glitch averages the last three outputs, the replaced value included.
  EXPECT_DOUBLE_EQ(r.cleaned[5].a_B.z(), (3.0 + 4.0 + 3.0) / 3);
  EXPECT_DOUBLE_EQ(r.cleaned[6].a_B.z(), 5.0);
}

TEST(ThresholdDetector, MeanMitigationWithoutHistoryClamps) {
  ThresholdOptions o = PaperBounds();
  o.mitigation = ThresholdMitigation::kMean;
  const DetectionResult r = DetectAndMitigate(DetectorOf(o), AzSeries({60.0, 1.0}));
  EXPECT_DOUBLE_EQ(r.cleaned[0].a_B.z(), 24.0);
}

TEST(ThresholdDetector, CalibrationWidensTheCleanRangeAboutItsCentre) {
  const ImuStream clean = AzSeries({-1.0, 4.0, 19.0, 3.0});
  ThresholdOptions o;
  o.calibration_margin = 1.2;
  const ThresholdBounds b = CalibrateThresholdBounds(clean, o);
  EXPECT_DOUBLE_EQ(b.lower[5], 9.0 - 1.2 * 10.0);
  EXPECT_DOUBLE_EQ(b.upper[5], 9.0 + 1.2 * 10.0);
  EXPECT_DOUBLE_EQ(b.lower[0], 0.0);  // a constant axis: its value only
  EXPECT_DOUBLE_EQ(b.upper[0], 0.0);
  const ThresholdOptions calibrated = WithBounds(o, b);
  EXPECT_EQ(calibrated.calibration, ThresholdCalibration::kManual);
  EXPECT_EQ(calibrated.upper, b.upper);
}

TEST(ThresholdDetector, CalibratedBoundsFlagNothingOnTheirCleanDataAndCatchLargeGlitches) {
  const ImuStream clean = testing::SyntheticImu(1000, 4000);
  const ThresholdOptions o = WithBounds(ThresholdOptions{}, CalibrateThresholdBounds(clean, {}));
  const DetectionResult on_clean = DetectAndMitigate(DetectorOf(o), clean);
  EXPECT_EQ(std::count(on_clean.flagged.begin(), on_clean.flagged.end(), 1), 0);

  const DetectionMetrics m = testing::Evaluate(DetectorOf(o), testing::Glitched(1, 4000, 50.0, 10.0, 0.01));
  EXPECT_GE(m.recall, 0.9);
  EXPECT_LT(m.imu_rmse_cleaned, m.imu_rmse_raw / 2);
}

TEST(ThresholdDetector, RejectsBadBounds) {
  ThresholdOptions o = PaperBounds();
  o.lower = {1.0, 2.0};
  EXPECT_NE(vigil::testing::InputErrorOf([&] { ThresholdDetector d(o); }).find("detector.threshold.lower"),
            std::string::npos);
  o = PaperBounds();
  o.lower[5] = 30.0;
  EXPECT_THROW(ThresholdDetector{o}, InputError);
}

}  // namespace
}  // namespace vigil::detectors
