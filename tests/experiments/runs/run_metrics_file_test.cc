#include "experiments/runs/run_metrics_file.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
using testing::InputErrorOf;
using testing::TempDir;

const char* kGoodMetrics =
    "{\n"
    "  \"status\": \"ok\",\n"
    "  \"seed\": 3,\n"
    "  \"ate\": {\"trans_m\": {\"rmse\": 0.05, \"n\": 100}},\n"
    "  \"relative\": [{\"distance_m\": 7.0, \"trans_m\": {\"mean\": 0.1, \"n\": 5}, \"yaw_deg\": {\"mean\": "
    "1}}],\n"
    "  \"detection\": {\"flagged_samples\": 4, \"recall\": null},\n"
    "  \"new_key\": {\"anything\": -1}\n"
    "}\n";

std::string MetricsWith(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

std::string ErrorOf(const TempDir& tmp, const std::string& text, uint64_t seed = 3) {
  const std::string path = tmp.File("metrics.json", text);
  return InputErrorOf([&] { (void)ReadRunMetrics(path, seed); });
}

TEST(RunMetricsFile, ARunsOwnMetricsAreRead) {
  TempDir tmp;
  EXPECT_EQ(ErrorOf(tmp, kGoodMetrics), "");
  // A run that failed before it started has only a status and a reason.
  EXPECT_EQ(ErrorOf(tmp, "{\"status\": \"failed\", \"failure_reason\": \"boom\"}"), "");
}

TEST(RunMetricsFile, AnotherRunsMetricsAreRefused) {
  TempDir tmp;
  const std::string error = ErrorOf(tmp, kGoodMetrics, 4);
  EXPECT_NE(error.find("metrics.json:3: seed: 3 is not this run's seed (4)"), std::string::npos) << error;
}

TEST(RunMetricsFile, CorruptValuesAreRefusedWithTheirLine) {
  TempDir tmp;
  EXPECT_NE(ErrorOf(tmp, MetricsWith(kGoodMetrics, "0.05", "-1"))
                .find(":4: ate.trans_m.rmse: must be in [0, 1e+09]"),
            std::string::npos);
  EXPECT_NE(ErrorOf(tmp, MetricsWith(kGoodMetrics, "0.05", "1e308")).find("ate.trans_m.rmse"),
            std::string::npos);
  EXPECT_NE(ErrorOf(tmp, MetricsWith(kGoodMetrics, "0.05", "\"x\""))
                .find("ate.trans_m.rmse: expected a number, got string"),
            std::string::npos);
  EXPECT_NE(ErrorOf(tmp, MetricsWith(kGoodMetrics, "0.05", "[1]")).find("expected a number, got array"),
            std::string::npos);
  EXPECT_NE(ErrorOf(tmp, MetricsWith(kGoodMetrics, "\"flagged_samples\": 4", "\"flagged_samples\": 1.5"))
                .find(":6: detection.flagged_samples"),
            std::string::npos);
  EXPECT_NE(ErrorOf(tmp, MetricsWith(kGoodMetrics, "\"ok\"", "\"fine\"")).find(":2: status"),
            std::string::npos);
  EXPECT_NE(ErrorOf(tmp, "[1, 2]").find("(top level): expected a JSON object, got array"), std::string::npos);
  EXPECT_NE(ErrorOf(tmp, "{\"status\": ").find("not valid JSON"), std::string::npos);
}

TEST(RunMetricsFile, KeysWithPointerCharactersAreCheckedNotThrown) {
  TempDir tmp;
  // '~' and '/' in a key the reader walks (found by fuzzing: it threw a JSON-pointer error).
  EXPECT_EQ(ErrorOf(tmp, "{\"status\": \"ok\", \"wall_time_s\": {\"si~ulate\": 0.1, \"a/b\": 1}}"), "");
  EXPECT_EQ(ErrorOf(tmp, "{\"status\": \"ok\",\n \"wall_time_s\": {\"x~/y\": -1}}"),
            tmp.path().string() + "/metrics.json:2: wall_time_s.x~/y: must be in [0, 1e+09], got -1");
}

}  // namespace
}  // namespace vigil::experiments
