// The accuracy regression gate: a sweep's per-cell means against a committed baseline.
//
// Cells compared: the mean ATE translation RMSE [m] and the failure count of every (group, method) of the
// sweep, and the pooled relative translation [m] and yaw [deg] errors of every (method, distance). A cell
// regresses when its value exceeds baseline x (1 + relative) + absolute (per metric; lower is better), when
// it has more failed runs than the baseline, or when it is missing or has no value where the baseline had
// one. Improvements beyond the same band are reported (time to record a new baseline) but do not fail.
// A baseline compares at least one cell (the baseline file and its reader: regression_baseline.h).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/sweeps/regression_baseline.h"
#include "experiments/sweeps/sweep_aggregate.h"

namespace vigil::experiments {

// The cells of a sweep (in table order).
std::vector<RegressionCell> RegressionCells(const SweepAggregate& agg);

nlohmann::json BaselineJson(const std::vector<RegressionCell>& cells, const RegressionTolerance& tolerance,
                            const std::string& sweep);

struct RegressionReport {
  std::size_t regressions = 0, improvements = 0, compared = 0;
  std::string text;  // a readable table of every cell, regressions marked
};

RegressionReport CompareWithBaseline(const std::vector<RegressionCell>& current,
                                     const std::vector<RegressionCell>& baseline,
                                     const RegressionTolerance& tolerance);

}  // namespace vigil::experiments
