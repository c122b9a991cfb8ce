#include "detectors/hampel_detector.h"

#include <gtest/gtest.h>

#include "detectors/detection_metrics.h"
#include "synthetic_imu.h"

namespace vigil::detectors {
namespace {

TEST(HampelDetector, ReplacesASpikeByTheWindowMedian) {
  ImuStream imu(21);
  for (int t = 0; t < 21; ++t) {
    imu[t].t_ns = t * 5000000LL;
    imu[t].a_B.z() = 9.81 + 0.01 * (t % 3);  // values 9.81, 9.82, 9.83
  }
  imu[10].a_B.z() = 60.0;
  HampelOptions options;
  options.half_window = 3;
  DetectorOptions det;
  det.type = DetectorType::kHampel;
  det.hampel = options;
  const DetectionResult r = DetectAndMitigate(det, imu);
  ASSERT_EQ(r.cleaned.size(), imu.size());
  for (int t = 0; t < 21; ++t) EXPECT_EQ(r.flagged[t], t == 10 ? 1 : 0) << t;
  // Window 7..13 without the spike: 9.82, 9.83, 9.81, 9.82, 9.83, 9.81 (+ 60): median 9.82.
  EXPECT_NEAR(r.cleaned[10].a_B.z(), 9.82, 1e-12);
}

TEST(HampelDetector, HoldsAtMostHalfWindowSamples) {
  HampelOptions options;
  options.half_window = 5;
  HampelDetector detector(options);
  const ImuStream imu = testing::SyntheticImu(3, 50);
  std::vector<DetectedSample> out;
  for (std::size_t t = 0; t < imu.size(); ++t) {
    detector.Push(imu[t], &out);
    EXPECT_LE(static_cast<int>(t + 1 - out.size()), detector.latency_samples());
  }
  detector.Finish(&out);
  ASSERT_EQ(out.size(), imu.size());
  for (std::size_t t = 0; t < imu.size(); ++t) EXPECT_EQ(out[t].sample.t_ns, imu[t].t_ns);
}

TEST(HampelDetector, FindsLargeGlitchesAndReducesTheError) {
  const ImuStream imu_clean = testing::SyntheticImu(1, 4000);
  ImuStream raw = imu_clean;
  const auto glitches = testing::InjectGlitches(&raw, 1, 50.0, 10.0, 0.01);
  DetectorOptions det;
  det.type = DetectorType::kHampel;
  const DetectionResult r = DetectAndMitigate(det, raw);
  const DetectionMetrics m = EvaluateDetection(raw, r, glitches, imu_clean);
  EXPECT_GE(m.recall, 0.99);
  EXPECT_LT(m.imu_rmse_cleaned, m.imu_rmse_raw / 5);
  // Six axes tested per sample: some clean samples are flagged, a small fraction.
  EXPECT_LT(m.false_positive_rate, 0.02);
}

}  // namespace
}  // namespace vigil::detectors
