#include "report/tables.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/format.h"
#include "core/output.h"
#include "core/staging.h"
#include "evaluation/statistics.h"
#include "experiments/sweeps/results_csv.h"
#include "report/paper_reference.h"
#include "report/reproduction.h"

namespace vigil::report {
namespace fs = std::filesystem;
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string> DistanceRows(const std::vector<double>& distances_m) {
  std::vector<std::string> rows;
  for (double d : distances_m) rows.push_back(FormatDouble(d) + " m");
  return rows;
}

ResultTable RelativeTable(const experiments::SweepAggregate& agg, const std::vector<std::string>& methods,
                          bool yaw) {
  ResultTable t;
  t.title =
      yaw ? "Table 4: overall relative yaw error [deg]" : "Table 3: overall relative translation error [m]";
  t.corner = "distance";
  t.columns = methods;
  t.rows = DistanceRows(agg.distances_m);
  t.decimals = 2;
  t.values.assign(t.rows.size(), std::vector<double>(methods.size(), kNaN));
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const int mi = agg.MethodIndex(methods[m]);
    if (mi < 0) continue;
    const experiments::CellResult pooled = agg.Pooled(static_cast<std::size_t>(mi));
    for (std::size_t d = 0; d < agg.distances_m.size(); ++d)
      t.values[d][m] = yaw ? pooled.PooledReYaw(d) : pooled.PooledReTrans(d);
  }
  return t;
}

}  // namespace

ResultTable MakeTable2(const experiments::SweepAggregate& agg, const std::vector<std::string>& methods) {
  ResultTable t;
  t.title = "Table 2: RMSE of translation [m] (absolute trajectory error), mean over seeds";
  t.corner = "method";
  t.columns = agg.groups;
  t.rows = methods;
  t.decimals = 2;
  t.values.assign(methods.size(), std::vector<double>(agg.groups.size(), kNaN));
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const int mi = agg.MethodIndex(methods[m]);
    if (mi < 0) continue;
    for (std::size_t g = 0; g < agg.groups.size(); ++g)
      t.values[m][g] =
          evaluation::ComputeStatistics(agg.Cell(g, static_cast<std::size_t>(mi)).ate_rmse_m).mean;
  }
  return t;
}

ResultTable MakeTable3(const experiments::SweepAggregate& agg, const std::vector<std::string>& methods) {
  return RelativeTable(agg, methods, false);
}
ResultTable MakeTable4(const experiments::SweepAggregate& agg, const std::vector<std::string>& methods) {
  return RelativeTable(agg, methods, true);
}

std::string SummaryMarkdown(const experiments::SweepSpec& spec, const experiments::SweepAggregate& agg) {
  std::size_t failed = 0, diverged = 0, inconclusive = 0;
  for (const auto& c : agg.cells) {
    failed += c.failed;
    diverged += c.diverged;
    inconclusive += c.inconclusive;
  }
  std::string s = "# Sweep summary\n\n";
  // File names only: the same summary wherever the sweep directory and the configs are.
  s += "Sweep: `" + fs::path(spec.path).filename().string() + "`; base configuration `" +
       spec.base.filename().string() + "`.\n\n";
  s += std::to_string(agg.runs) + " runs (" + std::to_string(agg.groups.size()) + " groups x " +
       std::to_string(agg.methods.size()) + " methods x " + std::to_string(spec.seeds.size()) +
       " seeds): " + std::to_string(agg.runs - failed - diverged - agg.missing) + " ok, " +
       std::to_string(diverged) + " diverged, " + std::to_string(failed) + " failed" +
       (inconclusive > 0 ? " (" + std::to_string(inconclusive) +
                               " of them inconclusive: too little coverage or motion for their errors to "
                               "mean anything, evaluation.min_coverage and evaluation.min_alignment_extent_m)"
                         : std::string()) +
       ", " + std::to_string(agg.missing) + " missing.\n\n";
  s += "Errors are over the runs that finished: ok and diverged (an ATE RMSE beyond the divergence bound, "
       "evaluation.divergence; counted in the diverged column), not failed ones. Relative errors are pooled "
       "over every sub-trajectory of every "
       "run "
       "(a run's mean weighted by its number of segments). Paper values (Long et al., IFAC 2020) in "
       "parentheses where the row and column names match.\n\n";

  s += "Methods (the sweep file's detector settings; the paper's are trunc = threshold, dtw = dtw with "
       "normalization none, original = none; the others are vigil's variants and extra baselines, "
       "detectors/detector_options.h gives each rule):\n\n";
  for (const experiments::SweepSetting& m : spec.methods) {
    s += "- `" + m.label + "`:";
    for (const experiments::SweepOverride& o : m.overrides)
      s += " `" + o.key + "=" + YAML::Dump(o.value) + "`";
    s += "\n";
  }
  s += "\n";

  const std::vector<std::string>& all = agg.methods;
  s += "## Tables of the paper\n\n";
  s += SideBySideMarkdown(MakeTable2(agg, all), PaperTable2()) + "\n";
  s += SideBySideMarkdown(MakeTable3(agg, all), PaperTable3()) + "\n";
  s += SideBySideMarkdown(MakeTable4(agg, all), PaperTable4()) + "\n";

  s += "## ATE translation RMSE [m] per cell\n\n";
  s += "| group | method | runs | ok | diverged | failed | missing | mean | std | median | min | max | "
       "detection precision | detection recall | false-positive rate |\n"
       "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t g = 0; g < agg.groups.size(); ++g) {
    for (std::size_t m = 0; m < agg.methods.size(); ++m) {
      const experiments::CellResult& c = agg.Cell(g, m);
      const evaluation::ErrorStatistics st = evaluation::ComputeStatistics(c.ate_rmse_m);
      s += "| " + agg.groups[g] + " | " + agg.methods[m] + " | " + std::to_string(c.runs) + " | " +
           std::to_string(c.ok()) + " | " + std::to_string(c.diverged) + " | " + std::to_string(c.failed) +
           " | " + std::to_string(c.missing) + " | " + FormatCell(st.mean) + " | " + FormatCell(st.std) +
           " | " + FormatCell(st.median) + " | " + FormatCell(st.min) + " | " + FormatCell(st.max) + " | " +
           FormatCell(c.Precision()) + " | " + FormatCell(c.Recall()) + " | " +
           FormatCell(c.FalsePositiveRate()) + " |\n";
    }
  }
  s += "\n## Relative translation error [m] per method, pooled over groups\n\n";
  s += "| method | distance | segments | pooled mean | std of run means | median of run means |\n"
       "|---|---:|---:|---:|---:|---:|\n";
  for (std::size_t m = 0; m < agg.methods.size(); ++m) {
    const experiments::CellResult pooled = agg.Pooled(m);
    for (std::size_t d = 0; d < agg.distances_m.size(); ++d) {
      const evaluation::ErrorStatistics st = evaluation::ComputeStatistics(pooled.re_trans_run_means[d]);
      s += "| " + agg.methods[m] + " | " + FormatDouble(agg.distances_m[d]) + " m | " +
           FormatDouble(pooled.re_n[d]) + " | " + FormatCell(pooled.PooledReTrans(d)) + " | " +
           FormatCell(st.std) + " | " + FormatCell(st.median) + " |\n";
    }
  }
  bool any_failure = false;
  std::string failures = "\n## Failures\n\n| group | method | count | reason |\n|---|---|---:|---|\n";
  for (std::size_t g = 0; g < agg.groups.size(); ++g)
    for (std::size_t m = 0; m < agg.methods.size(); ++m)
      for (const auto& [reason, count] : agg.Cell(g, m).failure_reasons) {
        any_failure = true;
        std::string r = reason;
        for (char& ch : r)
          if (ch == '|' || ch == '\n') ch = ' ';
        failures += "| " + agg.groups[g] + " | " + agg.methods[m] + " | " + std::to_string(count) + " | " +
                    r + " |\n";
      }
  s += any_failure ? failures : "\n## Failures\n\nNone.\n";
  return s;
}

experiments::SweepAggregate WriteSweepTables(const fs::path& dir) {
  const experiments::SweepSpec spec = experiments::LoadSweepSpec((dir / "sweep.yaml").string());
  const std::vector<double> distances = experiments::SweepDistances(spec);
  RemoveStaleStaging(dir);  // a killed sweep's results.csv.tmp-... (this host's dead processes only)
  experiments::ResultsCsvWriter csv(dir, spec, distances);
  const experiments::SweepAggregate agg = experiments::AggregateSweep(
      dir, spec, distances,
      [&](const experiments::SweepRunRef& run, const experiments::SweepCell& cell, const nlohmann::json* m) {
        if (m) csv.Add(run, cell, *m);
      });
  csv.Commit();
  WriteTableFiles(dir, spec, agg);
  return agg;
}

void WriteTableFiles(const fs::path& dir, const experiments::SweepSpec& spec,
                     const experiments::SweepAggregate& agg) {
  const ResultTable tables[] = {MakeTable2(agg, spec.table_methods), MakeTable3(agg, spec.table_methods),
                                MakeTable4(agg, spec.table_methods)};
  const char* names[] = {"table2", "table3", "table4"};
  for (int i = 0; i < 3; ++i) {
    WriteFileAtomic(dir / (std::string(names[i]) + ".md"), TableMarkdown(tables[i]));
    WriteFileAtomic(dir / (std::string(names[i]) + ".csv"), TableCsv(tables[i]));
    WriteFileAtomic(dir / (std::string(names[i]) + ".tex"), TableLatex(tables[i]));
  }
  WriteFileAtomic(dir / "summary.md", SummaryMarkdown(spec, agg));
  WriteReproduction(dir, spec);
}

}  // namespace vigil::report
