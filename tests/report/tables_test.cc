#include "report/tables.h"

#include <gtest/gtest.h>

#include "core/output.h"
#include "experiments/sweeps/regression.h"
#include "experiments/sweeps/sweep_runner.h"
#include "tests/core/test_util.h"
#include "tests/experiments/sweeps/sweep_test_util.h"

namespace vigil::report {
namespace {
namespace fs = std::filesystem;
using experiments::testing::FakeMetrics;
using experiments::testing::WriteSmallSweep;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

// Runs the small sweep with fake results; the run of `failing_id` throws.
experiments::SweepSpec RunFakeSweep(const TempDir& dir, const std::string& failing_id = "") {
  // Never read (the runs are fake), but a sweep refuses absent inputs.
  const std::string templates = dir.File("none.yaml", "# never read\n");
  const experiments::SweepSpec spec = experiments::LoadSweepSpec(WriteSmallSweep(
      dir, "  trunc: threshold\n  dtw: {type: dtw, dtw: {templates_file: " + templates +
               "}}\n  original: none\n  hampel: hampel\ntable_methods: [trunc, dtw, original]\n"));
  experiments::SweepRunOptions options;
  options.threads = 2;
  experiments::RunSweep(
      spec, dir.path() / "out", options,
      [&](const experiments::RunConfig& c, const experiments::RunOptions&, const fs::path& d) {
        if (!failing_id.empty() && d.filename().string().rfind(failing_id, 0) == 0)
          throw std::runtime_error("diverged: newest position jumped 7 m");
        return FakeMetrics(c);
      });
  return spec;
}

double Mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

TEST(Tables, Table2IsTheMeanAteOverSeedsWithThePapersLayout) {
  TempDir dir;
  const experiments::SweepSpec spec = RunFakeSweep(dir);
  const experiments::SweepAggregate agg = WriteSweepTables(dir.path() / "out");
  const ResultTable t2 = MakeTable2(agg, spec.table_methods);
  EXPECT_EQ(t2.rows, (std::vector<std::string>{"trunc", "dtw", "original"}));
  EXPECT_EQ(t2.columns, (std::vector<std::string>{"noise_0_1", "noise_50_10"}));
  // Expected: the fake metrics of the three seeds of (noise_50_10, original), by hand.
  std::vector<double> ates;
  for (uint64_t seed : {1, 2, 3}) {
    experiments::RunConfig c =
        experiments::ResolveCellConfig(spec, experiments::EnumerateCells(spec)[6]);  // noise_50_10 x original
    ASSERT_EQ(c.detector.type, detectors::DetectorType::kNone);
    c.seed = seed;
    ates.push_back(FakeMetrics(c)["ate"]["trans_m"]["rmse"].get<double>());
  }
  EXPECT_DOUBLE_EQ(t2.values[2][1], Mean(ates));
  EXPECT_GT(t2.values[2][1], 5 * t2.values[0][1]);  // the fake's "original" suffers from big glitches

  const std::string md = ReadFile(dir.path() / "out" / "table2.md");
  EXPECT_NE(md.find("| method | noise_0_1 | noise_50_10 |"), std::string::npos);
  const std::string tex = ReadFile(dir.path() / "out" / "table2.tex");
  for (const char* s : {"\\toprule", "\\midrule", "\\bottomrule", "noise\\_50\\_10", "original &"})
    EXPECT_NE(tex.find(s), std::string::npos) << s;
  const std::string csv = ReadFile(dir.path() / "out" / "table3.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "#distance,trunc,dtw,original");
  EXPECT_NE(csv.find("\n35 m,"), std::string::npos);
}

TEST(Tables, RelativeErrorsArePooledOverSegments) {
  TempDir dir;
  const experiments::SweepSpec spec = RunFakeSweep(dir);
  const experiments::SweepAggregate agg = WriteSweepTables(dir.path() / "out");
  // Pool by hand: trunc over both glitch settings and the three seeds, at 14 m.
  double weighted = 0, n = 0;
  const auto cells = experiments::EnumerateCells(spec);
  for (std::size_t c : {0u, 4u})
    for (uint64_t seed : {1, 2, 3}) {
      experiments::RunConfig config = experiments::ResolveCellConfig(spec, cells[c]);
      config.seed = seed;
      const auto m = FakeMetrics(config);
      weighted +=
          m["relative"][1]["trans_m"]["mean"].get<double>() * m["relative"][1]["trans_m"]["n"].get<double>();
      n += m["relative"][1]["trans_m"]["n"].get<double>();
    }
  const ResultTable t3 = MakeTable3(agg, spec.table_methods);
  EXPECT_EQ(t3.rows[1], "14 m");
  EXPECT_DOUBLE_EQ(t3.values[1][0], weighted / n);
}

TEST(Tables, SummaryCountsFailuresAndShowsExtraMethodsAndThePaper) {
  TempDir dir;
  RunFakeSweep(dir, "noise_50_10-original-s002");
  const experiments::SweepAggregate agg = WriteSweepTables(dir.path() / "out");
  const experiments::CellResult& cell = agg.Cell(1, 2);
  EXPECT_EQ(cell.failed, 1u);
  EXPECT_EQ(cell.ok(), 2u);
  const std::string summary = ReadFile(dir.path() / "out" / "summary.md");
  EXPECT_NE(summary.find("24 runs (2 groups x 4 methods x 3 seeds): 23 ok, 0 diverged, 1 failed, 0 missing"),
            std::string::npos);
  EXPECT_NE(summary.find("| noise_50_10 | original | 1 | diverged: newest position jumped 7 m |"),
            std::string::npos);
  EXPECT_NE(summary.find("| hampel |"), std::string::npos);  // not in the paper's tables, but summarized
  EXPECT_NE(summary.find("(18.05)"), std::string::npos);     // the paper's number beside ours
  const std::string results = ReadFile(dir.path() / "out" / "results.csv");
  EXPECT_NE(results.find("noise_50_10-original-s002,noise_50_10,original,2,failed,diverged: newest position"),
            std::string::npos);
  // Deleting a run makes it missing, and `tables` still works.
  fs::remove_all(dir.path() / "out" / "runs" / "noise_0_1-trunc-s001");
  EXPECT_EQ(WriteSweepTables(dir.path() / "out").missing, 1u);
}

TEST(Regression, IdenticalSweepPassesAndAWorseCellFails) {
  TempDir dir;
  RunFakeSweep(dir);
  const experiments::SweepAggregate agg = WriteSweepTables(dir.path() / "out");
  const auto cells = experiments::RegressionCells(agg);
  experiments::RegressionTolerance tol;
  const std::string path = dir.File("baseline.json", experiments::BaselineJson(cells, tol, "s.yaml").dump(2));
  std::vector<experiments::RegressionCell> baseline;
  experiments::RegressionTolerance read_tol;
  experiments::ReadBaseline(path, &baseline, &read_tol);
  ASSERT_EQ(baseline.size(), cells.size());
  EXPECT_EQ(read_tol.relative, tol.relative);
  EXPECT_EQ(experiments::CompareWithBaseline(cells, baseline, read_tol).regressions, 0u);

  auto worse = cells;
  worse[3].value = worse[3].value * 1.3 + 0.05;  // beyond 25 % + 0.02
  auto slightly = cells;
  slightly[3].value = slightly[3].value * 1.1;  // inside the tolerance
  auto failing = cells;
  failing[0].failed += 1;
  auto better = cells;
  better[0].value = 0.0;
  const experiments::RegressionReport r = experiments::CompareWithBaseline(worse, baseline, read_tol);
  EXPECT_EQ(r.regressions, 1u);
  EXPECT_NE(r.text.find("REGRESSED  ate_rmse_m   " + cells[3].cell), std::string::npos) << r.text;
  EXPECT_EQ(experiments::CompareWithBaseline(slightly, baseline, read_tol).regressions, 0u);
  EXPECT_EQ(experiments::CompareWithBaseline(failing, baseline, read_tol).regressions, 1u);
  const experiments::RegressionReport b = experiments::CompareWithBaseline(better, baseline, read_tol);
  EXPECT_EQ(b.regressions, 0u);
  EXPECT_EQ(b.improvements, 1u);
  std::vector<experiments::RegressionCell> fewer(cells.begin() + 1, cells.end());
  EXPECT_EQ(experiments::CompareWithBaseline(fewer, baseline, read_tol).regressions,
            1u);  // a cell went missing
}

TEST(Regression, MalformedBaselineIsAnInputError) {
  TempDir dir;
  EXPECT_EQ(InputErrorOf([&] {
              experiments::ReadBaseline(dir.File("b.json", "{\"format\": \"other\"}"), nullptr, nullptr);
            }),
            (dir.path() / "b.json").string() + ":1: format: expected \"vigil-regress-baseline-1\"");
  const std::string p = dir.File("c.json", "{\"format\": \"vigil-regress-baseline-1\", \"cells\": []}");
  std::vector<experiments::RegressionCell> cells;
  experiments::RegressionTolerance tol;
  EXPECT_NE(InputErrorOf([&] { experiments::ReadBaseline(p, &cells, &tol); }).find("c.json:1: tolerance: "),
            std::string::npos);
}

}  // namespace
}  // namespace vigil::report
