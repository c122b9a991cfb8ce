#include "detectors/detection_metrics.h"

#include <gtest/gtest.h>

namespace vigil::detectors {
namespace {

ImuStream Stream(int n) {
  ImuStream s(n);
  for (int t = 0; t < n; ++t) s[t].t_ns = 100 + 10 * t;
  return s;
}

TEST(DetectionMetrics, CountsPerSampleAndPerSegment) {
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
  EXPECT_DOUBLE_EQ(m.precision, 2.0 / 6.0);  // samples 2 and 10 of the six flagged
  EXPECT_DOUBLE_EQ(m.f1, 2 * (1.0 / 3.0) * (2.0 / 3.0) / (1.0 / 3.0 + 2.0 / 3.0));
  EXPECT_DOUBLE_EQ(m.segment_precision, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.segment_f1, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.false_positive_rate, 4.0 / 9.0);
}

TEST(DetectionMetrics, FlaggingEverySampleScoresTheGlitchFraction) {
  const ImuStream raw = Stream(200);
  std::vector<GlitchRecord> glitches;
  for (int t = 7; t < 200; t += 20) glitches.push_back({raw[t].t_ns, ImuAxis::kWx, 3.0});  // 10 of 200
  const DetectionResult everything{raw, std::vector<uint8_t>(raw.size(), 1)};
  const DetectionMetrics m = EvaluateDetection(raw, everything, glitches, {});
  EXPECT_DOUBLE_EQ(m.recall, 1.0);
  EXPECT_DOUBLE_EQ(m.precision, 10.0 / 200.0);
  EXPECT_LT(m.f1, 0.1);
  EXPECT_DOUBLE_EQ(m.false_positive_rate, 1.0);
  EXPECT_DOUBLE_EQ(m.segment_precision, 1.0);  // one segment holding every glitch: why it is not the headline

  // A detector that flags exactly the glitched samples scores 1 everywhere.
  DetectionResult exact{raw, std::vector<uint8_t>(raw.size(), 0)};
  for (int t = 7; t < 200; t += 20) exact.flagged[t] = 1;
  const DetectionMetrics e = EvaluateDetection(raw, exact, glitches, {});
  EXPECT_DOUBLE_EQ(e.precision, 1.0);
  EXPECT_DOUBLE_EQ(e.f1, 1.0);
  EXPECT_DOUBLE_EQ(e.false_positive_rate, 0.0);
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
  EXPECT_DOUBLE_EQ(m.precision, 0.0);  // one flagged sample, no glitch in it
  EXPECT_DOUBLE_EQ(m.segment_precision, 0.0);
}

TEST(DetectionMetrics, JsonHasTheKeysOfFormatsMd) {
  DetectionMetrics m;
  m.precision = 0.5;
  m.imu_rmse_raw = 2.0;
  const nlohmann::json j = DetectionJson(m, true, true);
  for (const char* key : {"flagged_samples", "glitched_samples", "precision", "recall", "f1",
                          "false_positive_rate", "segment_precision", "segment_f1", "flagged_fraction"})
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
