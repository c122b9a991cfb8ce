// Tables 2-4 of the paper regenerated from a sweep, and summary.md (every statistic behind them).
//
// Table 2: mean over seeds of the ATE translation RMSE [m], rows = methods (spec.table_methods, e.g. trunc /
// dtw / original), columns = groups (axis-setting combinations, e.g. the glitch settings).
// Tables 3 and 4: relative translation [m] and yaw [deg] errors per sub-trajectory length (rows "7 m" ...),
// pooled over every group and seed, columns = methods. Each is written as tableN.md, .csv and .tex.
#pragma once

#include <filesystem>

#include "experiments/sweeps/sweep_aggregate.h"
#include "experiments/sweeps/sweep_spec.h"
#include "report/result_table.h"

namespace vigil::report {

ResultTable MakeTable2(const experiments::SweepAggregate& agg, const std::vector<std::string>& methods);
ResultTable MakeTable3(const experiments::SweepAggregate& agg, const std::vector<std::string>& methods);
ResultTable MakeTable4(const experiments::SweepAggregate& agg, const std::vector<std::string>& methods);

// summary.md: run counts, the tables beside the paper's, per-cell std / median / min / max / failures,
// detection precision and recall, every method (extra ones included), failure reasons.
std::string SummaryMarkdown(const experiments::SweepSpec& spec, const experiments::SweepAggregate& agg);

// `vigil tables DIR`: reads DIR/sweep.yaml and runs/*/metrics.json; (re)writes results.csv, table2-4 and
// summary.md (each atomically). Returns the aggregate.
experiments::SweepAggregate WriteSweepTables(const std::filesystem::path& dir);

// table2-4 (.md, .csv, .tex), summary.md and, for the paper's grid, reproduction.md (reproduction.h) of an
// aggregate, each atomically (results.csv untouched).
void WriteTableFiles(const std::filesystem::path& dir, const experiments::SweepSpec& spec,
                     const experiments::SweepAggregate& agg);

}  // namespace vigil::report
