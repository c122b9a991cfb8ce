// The accuracy regression gate: a sweep's per-cell means against a committed baseline.
//
// Cells compared: the mean ATE translation RMSE [m] and the failure count of every (group, method) of the
// sweep, and the pooled relative translation [m] and yaw [deg] errors of every (method, distance). A cell
// regresses when its value exceeds baseline x (1 + relative) + absolute (per metric; lower is better), when
// it has more failed runs than the baseline, or when it is missing or has no value where the baseline had
// one. Improvements beyond the same band are reported (time to record a new baseline) but do not fail.
//
// Baseline file (JSON, under experiments/baselines/):
//   {"format": "vigil-regress-baseline-1", "sweep": "<sweep file>",
//    "tolerance": {"relative": 0.25, "absolute": {"ate_rmse_m": 0.02, "re_trans_m": 0.02, "re_yaw_deg":
//    0.1}}, "cells": [{"metric": "ate_rmse_m", "cell": "noise_0_1/trunc", "value": 0.05, "failed": 0}, ...]}
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/sweep_aggregate.h"

namespace vigil::experiments {

struct RegressionTolerance {
  double relative = 0.25;
  std::map<std::string, double> absolute = {{"ate_rmse_m", 0.02}, {"re_trans_m", 0.02}, {"re_yaw_deg", 0.1}};
};

struct RegressionCell {
  std::string metric, cell;  // e.g. "ate_rmse_m", "noise_0_1/trunc"; "re_yaw_deg", "trunc/7m"
  double value = 0.0;        // NaN when the cell has no successful run
  long failed = 0;
};

// The cells of a sweep (in table order).
std::vector<RegressionCell> RegressionCells(const SweepAggregate& agg);

nlohmann::json BaselineJson(const std::vector<RegressionCell>& cells, const RegressionTolerance& tolerance,
                            const std::string& sweep);
// Reads a baseline file; InputError "file: key: reason" when malformed.
void ReadBaseline(const std::string& path, std::vector<RegressionCell>* cells,
                  RegressionTolerance* tolerance);

struct RegressionReport {
  std::size_t regressions = 0, improvements = 0, compared = 0;
  std::string text;  // a readable table of every cell, regressions marked
};

RegressionReport CompareWithBaseline(const std::vector<RegressionCell>& current,
                                     const std::vector<RegressionCell>& baseline,
                                     const RegressionTolerance& tolerance);

}  // namespace vigil::experiments
