#include "experiments/sweeps/regression.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.h"
#include "core/format.h"
#include "core/output.h"
#include "evaluation/metrics_access.h"
#include "evaluation/statistics.h"

namespace vigil::experiments {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string Show(double v) {
  if (!std::isfinite(v)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

std::vector<RegressionCell> RegressionCells(const SweepAggregate& agg) {
  std::vector<RegressionCell> cells;
  for (std::size_t g = 0; g < agg.groups.size(); ++g)
    for (std::size_t m = 0; m < agg.methods.size(); ++m) {
      const CellResult& c = agg.Cell(g, m);
      cells.push_back({"ate_rmse_m", agg.groups[g] + "/" + agg.methods[m],
                       evaluation::ComputeStatistics(c.ate_rmse_m).mean,
                       static_cast<long>(c.failed + c.missing)});
    }
  for (std::size_t m = 0; m < agg.methods.size(); ++m) {
    const CellResult pooled = agg.Pooled(m);
    for (std::size_t d = 0; d < agg.distances_m.size(); ++d) {
      const std::string cell = agg.methods[m] + "/" + FormatDouble(agg.distances_m[d]) + "m";
      cells.push_back({"re_trans_m", cell, pooled.PooledReTrans(d), 0});
      cells.push_back({"re_yaw_deg", cell, pooled.PooledReYaw(d), 0});
    }
  }
  return cells;
}

nlohmann::json BaselineJson(const std::vector<RegressionCell>& cells, const RegressionTolerance& tolerance,
                            const std::string& sweep) {
  nlohmann::json j;
  j["format"] = kBaselineFormat;
  j["sweep"] = sweep;
  j["tolerance"] = {{"relative", tolerance.relative}, {"absolute", tolerance.absolute}};
  j["cells"] = nlohmann::json::array();
  for (const auto& c : cells) {
    nlohmann::json cell = {{"metric", c.metric}, {"cell", c.cell}, {"failed", c.failed}};
    cell["value"] = evaluation::NumberOrNull(c.value);
    j["cells"].push_back(cell);
  }
  return j;
}

RegressionReport CompareWithBaseline(const std::vector<RegressionCell>& current,
                                     const std::vector<RegressionCell>& baseline,
                                     const RegressionTolerance& tolerance) {
  RegressionReport report;
  char line[512];
  std::snprintf(line, sizeof line, "%-10s %-12s %-28s %10s %10s %10s %7s %7s\n", "status", "metric", "cell",
                "baseline", "current", "limit", "failed", "(base)");
  report.text = line;
  for (const RegressionCell& base : baseline) {
    const RegressionCell* now = nullptr;
    for (const auto& c : current)
      if (c.metric == base.metric && c.cell == base.cell) now = &c;
    const auto abs_it = tolerance.absolute.find(base.metric);
    const double absolute = abs_it != tolerance.absolute.end() ? abs_it->second : 0.0;
    const double limit = std::isfinite(base.value) ? base.value * (1 + tolerance.relative) + absolute : kNaN;
    const double floor = std::isfinite(base.value) ? base.value * (1 - tolerance.relative) - absolute : kNaN;
    std::string status = "ok";
    if (!now) {
      status = "MISSING";
    } else if (now->failed > base.failed) {
      status = "REGRESSED";
    } else if (std::isfinite(base.value) && !std::isfinite(now->value)) {
      status = "REGRESSED";
    } else if (std::isfinite(base.value) && now->value > limit) {
      status = "REGRESSED";
    } else if (std::isfinite(base.value) && now->value < floor) {
      status = "improved";
    }
    ++report.compared;
    if (status == "MISSING" || status == "REGRESSED") ++report.regressions;
    if (status == "improved") ++report.improvements;
    std::snprintf(line, sizeof line, "%-10s %-12s %-28s %10s %10s %10s %7s %7ld\n", status.c_str(),
                  base.metric.c_str(), base.cell.c_str(), Show(base.value).c_str(),
                  now ? Show(now->value).c_str() : "-", Show(limit).c_str(),
                  now ? std::to_string(now->failed).c_str() : "-", base.failed);
    report.text += line;
  }
  for (const auto& c : current) {
    bool known = false;
    for (const auto& b : baseline) known = known || (b.metric == c.metric && b.cell == c.cell);
    if (!known) {
      std::snprintf(line, sizeof line, "%-10s %-12s %-28s %10s %10s\n", "new", c.metric.c_str(),
                    c.cell.c_str(), "-", Show(c.value).c_str());
      report.text += line;
    }
  }
  return report;
}

}  // namespace vigil::experiments
