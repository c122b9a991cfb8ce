#include "detectors/detection_metrics.h"

#include <gtest/gtest.h>

namespace vigil::detectors {
namespace {

ImuStream Stream(int n) {
  ImuStream s(n);
  for (int t = 0; t < n; ++t) s[t].t_ns = 100 + 10 * t;
  return s;
}

TEST(DetectionMetrics, CountsRecallPerSampleAndPrecisionPerSegment) {
  const ImuStream raw = Stream(12);
  DetectionResult r{raw, {0, 1, 1, 1, 0, 0, 1, 0, 0, 1, 1, 0}};
  // Glitches at samples 2 (two axes: one sample), 5 and 10.
  const std::vector<GlitchRecord> glitches = {{raw[2].t_ns, ImuAxis::kAz, 5.0},
                                              {raw[2].t_ns, ImuAxis::kAx, 1.0},
                                              {raw[5].t_ns, ImuAxis::kAz, 1.0},
                                              {raw[10].t_ns, ImuAxis::kAz, 1.0},
                                              {999999, ImuAxis::kAz, 1.0} /* not a sample: ignored */};
  const DetectionMetrics m = EvaluateDetection(raw, r, glitches, {});
  EXPECT_EQ(m.samples, 12);
  EXPECT_EQ(m.flagged_samples, 6);
  EXPECT_EQ(m.glitched_samples, 3);
  EXPECT_EQ(m.detected_glitched_samples, 2);
  EXPECT_EQ(m.flagged_segments, 3);  // [1, 3], [6], [9, 10]
  EXPECT_EQ(m.true_segments, 2);
  EXPECT_DOUBLE_EQ(m.recall, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.precision, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.f1, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.false_positive_rate, 4.0 / 9.0);
}

TEST(DetectionMetrics, RmsDifferenceToTheCleanStream) {
  const ImuStream clean = Stream(4);
  ImuStream raw = clean;
  raw[1].a_B.z() = 4.0;  // one sample off by (0, 0, 4) and (3, 0, 0): norm 5
  raw[1].w_B.x() = 3.0;
  DetectionResult r{clean, std::vector<uint8_t>(4, 0)};
  r.flagged[1] = 1;
  const DetectionMetrics m = EvaluateDetection(raw, r, {}, clean);
  EXPECT_DOUBLE_EQ(m.imu_rmse_raw, std::sqrt(25.0 / 4));
  EXPECT_DOUBLE_EQ(m.imu_rmse_cleaned, 0.0);
  EXPECT_DOUBLE_EQ(m.recall, 1.0);     // nothing to find
  EXPECT_DOUBLE_EQ(m.precision, 0.0);  // one flagged segment, no glitch in it
}

TEST(DetectionMetrics, JsonHasTheKeysOfFormatsMd) {
  DetectionMetrics m;
  m.precision = 0.5;
  m.imu_rmse_raw = 2.0;
  const nlohmann::json j = DetectionJson(m, true, true);
  for (const char* key : {"flagged_samples", "glitched_samples", "precision", "recall", "f1"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["imu_rmse_vs_clean"]["raw"], 2.0);
  const nlohmann::json bare = DetectionJson(m, false, false);
  EXPECT_FALSE(bare.contains("precision"));
  EXPECT_FALSE(bare.contains("imu_rmse_vs_clean"));
}

TEST(DetectionMetrics, RejectsMismatchedLengths) {
  const ImuStream raw = Stream(3);
  EXPECT_THROW(EvaluateDetection(raw, {raw, {0, 0}}, {}, {}), std::invalid_argument);
  EXPECT_THROW(EvaluateDetection(raw, {raw, {0, 0, 0}}, {}, Stream(2)), std::invalid_argument);
}

}  // namespace
}  // namespace vigil::detectors
