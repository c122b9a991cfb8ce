#include "detectors/detector.h"

#include <gtest/gtest.h>

#include "detectors/detection_metrics.h"
#include "detectors/template_library.h"
#include "tests/core/test_util.h"
#include "tests/detectors/detector_fixtures.h"

namespace vigil::detectors {
namespace {

// Every detector: one output per input, timestamps unchanged, bounded latency, and the same output whether
// the stream is consumed sample by sample or as a whole.
TEST(Detector, EveryDetectorStreamsEverySampleOnceWithBoundedLatency) {
  const TemplateLibrary library = testing::SyntheticTemplates();
  const ImuStream raw = testing::Glitched(4, 1234, 50.0, 10.0, 0.02).raw;
  for (const auto& [name, type] : DetectorTypeNames()) {
    SCOPED_TRACE(name);
    const DetectorOptions options = testing::DetectorOf(type);
    const std::unique_ptr<Detector> detector = MakeDetector(options, &library);
    const std::vector<DetectedSample> out = testing::StreamThrough(*detector, raw);
    ASSERT_EQ(out.size(), raw.size()) << name;
    const DetectionResult whole = DetectAndMitigate(options, raw, &library);
    for (std::size_t t = 0; t < raw.size(); ++t) {
      ASSERT_EQ(whole.cleaned[t].t_ns, raw[t].t_ns) << name;
      ASSERT_EQ(whole.cleaned[t].a_B, out[t].sample.a_B) << name;
      ASSERT_EQ(whole.flagged[t], out[t].flagged_axes != 0 ? 1 : 0) << name;
      // Unflagged samples pass unchanged.
      if (!whole.flagged[t]) {
        ASSERT_EQ(whole.cleaned[t].a_B, raw[t].a_B) << name << " " << t;
      }
    }
  }
}

TEST(Detector, NoneFlagsNothingAndChangesNothing) {
  const ImuStream raw = testing::SyntheticImu(1, 100);
  const DetectionResult r = DetectAndMitigate({}, raw);
  EXPECT_EQ(std::count(r.flagged.begin(), r.flagged.end(), 1), 0);
  for (std::size_t t = 0; t < raw.size(); ++t) EXPECT_EQ(r.cleaned[t].a_B, raw[t].a_B);
}

// N(0, 1) glitches sit inside the sensor noise: no detector should raise many alarms on them.
TEST(Detector, SmallGlitchesRaiseFewFalseAlarms) {
  const TemplateLibrary library = testing::SyntheticTemplates();
  const testing::GlitchedRun run = testing::Glitched(2, 4001, 0.0, 1.0, 0.01);
  for (DetectorType type : {DetectorType::kRelativeThreshold, DetectorType::kDtw}) {
    const DetectionMetrics m = testing::Evaluate(testing::DetectorOf(type), run, &library);
    EXPECT_LT(m.false_positive_rate, 0.02) << static_cast<int>(type);
  }
}

}  // namespace
}  // namespace vigil::detectors

namespace vigil::detectors {
namespace {

TEST(Detector, ValidatesCrossFieldOptions) {
  DetectorOptions options;
  options.relative_threshold.bounds = {1.0, 1.0};
  EXPECT_NE(vigil::testing::InputErrorOf([&] {
              ValidateDetectorOptions(options);
            }).find("detector.relative_threshold.bounds"),
            std::string::npos);
  options = {};
  options.dtw.dims = 4;
  EXPECT_NE(vigil::testing::InputErrorOf([&] { MakeDetector(options); }).find("detector.dtw.dims"),
            std::string::npos);
  options = {};
  options.dtw.template_length = 50;
  EXPECT_NE(vigil::testing::InputErrorOf([&] { ValidateDetectorOptions(options); }).find("template_length"),
            std::string::npos);
  EXPECT_NO_THROW(ValidateDetectorOptions({}));
}

}  // namespace
}  // namespace vigil::detectors

namespace vigil::detectors {
namespace {

TEST(Detector, EmptyAndTinyStreams) {
  const TemplateLibrary library = testing::SyntheticTemplates();
  for (const auto& [name, type] : DetectorTypeNames()) {
    const DetectorOptions options = testing::DetectorOf(type);
    EXPECT_TRUE(DetectAndMitigate(options, {}, &library).cleaned.empty()) << name;
    const ImuStream tiny = testing::SyntheticImu(1, 5);  // shorter than a DTW slice and a Hampel window
    const DetectionResult r = DetectAndMitigate(options, tiny, &library);
    ASSERT_EQ(r.cleaned.size(), tiny.size()) << name;
  }
}

}  // namespace
}  // namespace vigil::detectors
