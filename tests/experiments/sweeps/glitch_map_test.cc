// Glitch maps and detector ROC read back from a sweep directory's metrics.json files (nothing re-run), and
// sweep methods that set estimator keys.
#include "experiments/sweeps/glitch_map.h"

#include <fstream>

#include <gtest/gtest.h>

#include "experiments/sweeps/detection_roc.h"
#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

constexpr const char* kMapSweep =
    "base: base.yaml\n"
    "axes:\n"
    "  glitch:\n"
    "    none: {mean: 0, std: 0}\n"
    "    m50: {mean: 50, std: 10}\n"
    "  glitch.rate: [0.01, 0.05]\n"
    "methods:\n"
    "  original: none\n"
    "  trunc_gate: {type: threshold, estimator.mitigation.gating.enabled: true}\n"
    "seeds: [1, 2]\n";

void WriteMetrics(const fs::path& dir, const std::string& id, const std::string& json) {
  fs::create_directories(dir / "runs" / id);
  std::ofstream(dir / "runs" / id / "metrics.json") << json;
}

std::string Ok(double ate) {
  return "{\"status\": \"ok\", \"failure_reason\": \"\", \"ate\": {\"trans_m\": {\"rmse\": " +
         std::to_string(ate) + "}}}";
}

TEST(GlitchMap, RatiosAgainstTheReferenceOfTheSameMethodAndSeeds) {
  TempDir dir;
  dir.File("base.yaml", "duration_s: 3\n");
  const SweepSpec spec = LoadSweepSpec(dir.File("map.yaml", kMapSweep));
  // The method sets an estimator key next to the detector's.
  const RunConfig gated = ResolveCellConfig(spec, EnumerateCells(spec)[1]);
  EXPECT_TRUE(gated.estimator.mitigation.gating.enabled);
  EXPECT_EQ(gated.detector.type, detectors::DetectorType::kThreshold);
  const fs::path out = dir.path() / "sweep";
  for (const char* rate : {"rate_0.01", "rate_0.05"}) {
    for (const char* seed : {"s001", "s002"}) {
      const bool second = std::string(seed) == "s002";
      WriteMetrics(out, std::string("none-") + rate + "-original-" + seed, Ok(second ? 0.2 : 0.1));
      WriteMetrics(out, std::string("none-") + rate + "-trunc_gate-" + seed, Ok(0.1));
      WriteMetrics(out, std::string("m50-") + rate + "-original-" + seed, Ok(second ? 2.0 : 1.0));
    }
    WriteMetrics(out, std::string("m50-") + rate + "-trunc_gate-s001", Ok(0.11));
  }
  WriteMetrics(out, "m50-rate_0.01-trunc_gate-s002", "{\"status\": \"failed\", \"failure_reason\": \"x\"}");
  WriteMetrics(out, "m50-rate_0.05-trunc_gate-s002", Ok(0.13));
  const GlitchMap map = ReadGlitchMap(out, spec);
  ASSERT_EQ(map.rows, (std::vector<std::string>{"m50"}));
  ASSERT_EQ(map.columns, (std::vector<std::string>{"rate_0.01", "rate_0.05"}));
  EXPECT_EQ(map.reference, "none");
  EXPECT_NEAR(map.Cell(0, 0, 0).ratio, 3.0 / 0.3, 1e-12);  // mean 1.5 / mean 0.15
  EXPECT_TRUE(std::isnan(map.Cell(1, 0, 0).ratio));        // a failed run: no ratio
  EXPECT_EQ(map.Cell(1, 0, 0).failed, 1);
  EXPECT_NEAR(map.Cell(1, 0, 1).ratio, 0.24 / 0.2, 1e-12);
  EXPECT_EQ(map.BestMethod(0, 0), 0);
  EXPECT_EQ(map.BestMethod(0, 1), 1);
  const std::string md = GlitchMapMarkdown(map);
  EXPECT_NE(md.find("| m50 | 10.00 | 10.00 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| m50 | - (1 F) | 1.20 |"), std::string::npos) << md;
  EXPECT_NE(md.find("within 1.20x the glitch-free ATE in 1 of 2 cells"), std::string::npos) << md;
}

TEST(GlitchMap, NeedsTwoAxes) {
  TempDir dir;
  dir.File("base.yaml", "duration_s: 3\n");
  const SweepSpec spec =
      LoadSweepSpec(dir.File("one.yaml",
                             "base: base.yaml\naxes:\n  glitch.rate: [0, 0.1]\nmethods: {a: none}\n"
                             "seeds: [1]\n"));
  EXPECT_NE(InputErrorOf([&] { ReadGlitchMap(dir.path(), spec); }).find("exactly two axes"),
            std::string::npos);
}

TEST(DetectionRoc, PoolsSampleCountsPerThresholdPoint) {
  TempDir dir;
  dir.File("base.yaml", "duration_s: 3\n");
  const SweepSpec spec =
      LoadSweepSpec(dir.File("roc.yaml",
                             "base: base.yaml\nmethods:\n  hampel_3: {type: hampel, hampel.n_sigma: 3}\n"
                             "  hampel_6: {type: hampel, hampel.n_sigma: 6}\nseeds: [1, 2]\n"));
  const auto detection = [](int flagged, int detected) {
    return "{\"status\": \"ok\", \"detection\": {\"samples\": 1000, \"flagged_samples\": " +
           std::to_string(flagged) +
           ", \"glitched_samples\": 10, \"detected_glitched_samples\": " + std::to_string(detected) + "}}";
  };
  const fs::path out = dir.path() / "sweep";
  WriteMetrics(out, "hampel_3-s001", detection(20, 10));
  WriteMetrics(out, "hampel_3-s002", detection(12, 8));
  WriteMetrics(out, "hampel_6-s001", detection(5, 5));
  const std::vector<RocCurve> curves = ReadDetectionRoc(out, spec);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_EQ(curves[0].detector, "hampel");
  ASSERT_EQ(curves[0].points.size(), 2u);
  EXPECT_NEAR(curves[0].points[0].tpr, 18.0 / 20.0, 1e-12);
  EXPECT_NEAR(curves[0].points[0].fpr, 14.0 / 1980.0, 1e-12);
  EXPECT_NEAR(curves[0].points[1].fpr, 0.0, 1e-12);
  EXPECT_EQ(curves[0].points[1].runs, 1);
}

}  // namespace
}  // namespace vigil::experiments
