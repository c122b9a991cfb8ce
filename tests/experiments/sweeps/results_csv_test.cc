#include "experiments/sweeps/results_csv.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {

// The last comma-separated field of a line.
std::string LastField(const std::string& line) { return line.substr(line.rfind(',') + 1); }

TEST(ResultsCsv, CoverageAndTheExternalProcessTimeAreTheLastColumns) {
  vigil::testing::TempDir tmp;
  SweepSpec spec;
  spec.methods.push_back({"ext", {}});
  const ResultsCsvWriter writer(tmp.path(), spec, {});
  const SweepRunRef run{0, 0, 1, "ext-s001"};
  const SweepCell cell{{}, 0};
  const nlohmann::json external = {{"status", "ok"},
                                   {"failure_reason", ""},
                                   {"coverage", 0.887},
                                   {"wall_time_s", {{"estimate", 2.5}}},
                                   {"external", {{"wall_time_s", {{"process", 2.25}}}}}};
  const nlohmann::json builtin = {
      {"status", "ok"}, {"failure_reason", ""}, {"coverage", 1.0}, {"wall_time_s", {{"estimate", 1.5}}}};

  EXPECT_EQ(LastField(writer.Header()), "coverage");
  EXPECT_EQ(LastField(writer.Row(run, cell, external)), "0.887");
  EXPECT_EQ(LastField(writer.Row(run, cell, builtin)), "1");
  EXPECT_EQ(LastField(ResultsCsvWriter::TimingHeader()), "external_process_s");
  EXPECT_EQ(LastField(ResultsCsvWriter::TimingRow(run, external)), "2.25");
  EXPECT_EQ(LastField(ResultsCsvWriter::TimingRow(run, builtin)), "");  // vigil's own: no process
  // The columns before them are where they were (readers by position keep working).
  EXPECT_EQ(ResultsCsvWriter::TimingHeader().rfind("#id,simulate_s,templates_s,detect_s,estimate_s,", 0), 0u);
}

}  // namespace
}  // namespace vigil::experiments
