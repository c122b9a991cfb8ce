#include "detectors/hampel_detector.h"

#include <gtest/gtest.h>

#include "tests/detectors/detector_fixtures.h"

namespace vigil::detectors {
namespace {

TEST(HampelDetector, ReplacesASpikeByTheWindowMedian) {
  std::vector<double> az;
  for (int t = 0; t < 21; ++t) az.push_back(9.81 + 0.01 * (t % 3));  // values 9.81, 9.82, 9.83
  az[10] = 60.0;
  const ImuStream imu = testing::AzSeries(az);
  HampelOptions options;
  options.half_window = 3;
  const DetectionResult r = DetectAndMitigate(testing::DetectorOf(options), imu);
  ASSERT_EQ(r.cleaned.size(), imu.size());
  for (int t = 0; t < 21; ++t) EXPECT_EQ(r.flagged[t], t == 10 ? 1 : 0) << t;
  // Window 7..13 without the spike: 9.82, 9.83, 9.81, 9.82, 9.83, 9.81 (+ 60): median 9.82.
  EXPECT_NEAR(r.cleaned[10].a_B.z(), 9.82, 1e-12);
}

TEST(HampelDetector, HoldsAtMostHalfWindowSamples) {
  HampelOptions options;
  options.half_window = 5;
  HampelDetector detector(options);
  EXPECT_EQ(detector.latency_samples(), 5);
  testing::StreamThrough(detector, testing::SyntheticImu(3, 50));
}

TEST(HampelDetector, FindsLargeGlitchesAndReducesTheError) {
  const DetectionMetrics m = testing::Evaluate(testing::DetectorOf(DetectorType::kHampel),
                                               testing::Glitched(1, 4000, 50.0, 10.0, 0.01));
  EXPECT_GE(m.recall, 0.99);
  EXPECT_LT(m.imu_rmse_cleaned, m.imu_rmse_raw / 5);
  // Six axes tested per sample: some clean samples are flagged, a small fraction.
  EXPECT_LT(m.false_positive_rate, 0.02);
}

}  // namespace
}  // namespace vigil::detectors
