#include "experiments/sweeps/regression_baseline.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
using testing::InputErrorOf;
using testing::TempDir;

const char* kGood =
    "{\n"
    "  \"cells\": [\n"
    "    {\"cell\": \"noise_0_1/trunc\", \"failed\": 0, \"metric\": \"ate_rmse_m\", \"value\": 0.05}\n"
    "  ],\n"
    "  \"format\": \"vigil-regress-baseline-1\",\n"
    "  \"sweep\": \"configs/ci_sweep.yaml\",\n"
    "  \"tolerance\": {\"absolute\": {\"ate_rmse_m\": 0.02}, \"relative\": 0.25}\n"
    "}\n";

std::string ReadError(const TempDir& tmp, const std::string& text) {
  const std::string path = tmp.File("b.json", text);
  std::vector<RegressionCell> cells;
  RegressionTolerance tolerance;
  return InputErrorOf([&] { ReadBaseline(path, &cells, &tolerance); });
}

std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(RegressionBaseline, AValidBaselineIsRead) {
  TempDir tmp;
  const std::string path = tmp.File("b.json", kGood);
  std::vector<RegressionCell> cells;
  RegressionTolerance tolerance;
  ReadBaseline(path, &cells, &tolerance);
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_EQ(cells[0].cell, "noise_0_1/trunc");
  EXPECT_DOUBLE_EQ(cells[0].value, 0.05);
  EXPECT_DOUBLE_EQ(tolerance.absolute.at("ate_rmse_m"), 0.02);
  EXPECT_TRUE(IsBaselineFile(path));
}

TEST(RegressionBaseline, ABaselineThatComparesNothingIsRefused) {
  TempDir tmp;
  const std::string cells = kGood;
  const std::string empty = cells.substr(0, cells.find("[")) + "[]," + cells.substr(cells.find("],") + 2);
  EXPECT_EQ(ReadError(tmp, empty),
            tmp.path().string() + "/b.json:2: cells: no cells (a baseline must compare at least one)");
  EXPECT_NE(ReadError(tmp, Replaced(empty, "[]", "{}")).find("cells: expected an array of cells, got object"),
            std::string::npos);
}

TEST(RegressionBaseline, ANullValueWithoutFailedRunsIsRefused) {
  TempDir tmp;
  const std::string error = ReadError(tmp, Replaced(kGood, "0.05}", "null}"));
  EXPECT_NE(error.find("b.json:3: cells[0].value: null but no run failed"), std::string::npos) << error;
  // null with failed runs is how a cell whose runs all failed is recorded.
  EXPECT_EQ(ReadError(tmp, Replaced(Replaced(kGood, "0.05}", "null}"), "\"failed\": 0", "\"failed\": 2")),
            "");
}

TEST(RegressionBaseline, MistypedOrOutOfRangeValuesNameTheirLine) {
  TempDir tmp;
  EXPECT_NE(ReadError(tmp, Replaced(kGood, "0.05}", "-1}"))
                .find(":3: cells[0].value: must be a finite number >= 0"),
            std::string::npos);
  EXPECT_NE(
      ReadError(tmp, Replaced(kGood, "0.05}", "\"0.05\"}")).find(":3: cells[0].value: expected a number"),
      std::string::npos);
  EXPECT_NE(
      ReadError(tmp, Replaced(kGood, "ate_rmse_m\", \"value", "foo\", \"value")).find("cells[0].metric"),
      std::string::npos);
  EXPECT_NE(ReadError(tmp, Replaced(kGood, "\"relative\": 0.25", "\"relative\": -1"))
                .find(":7: tolerance.relative"),
            std::string::npos);
  EXPECT_NE(
      ReadError(tmp, Replaced(kGood, "\"sweep\"", "\"extra\": 1, \"sweep\"")).find(":6: extra: unknown key"),
      std::string::npos);
}

TEST(RegressionBaseline, InvalidJsonGivesOneLineWithItsLine) {
  TempDir tmp;
  const std::string error = ReadError(tmp, Replaced(kGood, "\"format\"", "format"));
  EXPECT_NE(error.find("b.json:5: not valid JSON: "), std::string::npos) << error;
  EXPECT_EQ(error.find("json.exception"), std::string::npos) << error;
}

TEST(RegressionBaseline, OnlyABaselineIsRecognisedAsOne) {
  TempDir tmp;
  EXPECT_FALSE(IsBaselineFile(tmp.File("notes.txt", "my notes\n")));
  EXPECT_FALSE(IsBaselineFile(tmp.File("other.json", "{\"format\": \"something\"}")));
}

}  // namespace
}  // namespace vigil::experiments
