// The regression gate's baseline file (experiments/baselines/*.json; the gate itself: regression.h):
//   {"format": "vigil-regress-baseline-1", "sweep": "<sweep file>",
//    "tolerance": {"relative": 0.25, "absolute": {"ate_rmse_m": 0.02, "re_trans_m": 0.02, "re_yaw_deg":
//    0.1}}, "cells": [{"metric": "ate_rmse_m", "cell": "noise_0_1/trunc", "value": 0.05, "failed": 0}, ...]}
// metric is one of ate_rmse_m, re_trans_m, re_yaw_deg; value a finite number >= 0, or null for a cell whose
// runs all failed (then failed > 0); failed an integer >= 0. At least one cell; no cell twice; no other key.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/output.h"

namespace vigil::experiments {

inline constexpr const char* kBaselineFormat = "vigil-regress-baseline-1";

struct RegressionTolerance {
  double relative = 0.25;
  std::map<std::string, double> absolute = {{"ate_rmse_m", 0.02}, {"re_trans_m", 0.02}, {"re_yaw_deg", 0.1}};
};

struct RegressionCell {
  std::string metric, cell;  // e.g. "ate_rmse_m", "noise_0_1/trunc"; "re_yaw_deg", "trunc/7m"
  double value = 0.0;        // NaN when the cell has no successful run
  long failed = 0;
};

// ate_rmse_m, re_trans_m or re_yaw_deg.
bool IsRegressionMetric(const std::string& metric);

// Reads a baseline file, checked against the schema above; InputError "file:line: key: reason" when
// malformed: not JSON, a missing or mistyped key, an unknown key or metric, a negative or non-finite number,
// no cells (a gate that compares nothing), a duplicate cell, or a null value where no run failed.
void ReadBaseline(const std::string& path, std::vector<RegressionCell>* cells,
                  RegressionTolerance* tolerance);
// The same on a file already in memory.
void ReadBaselineText(const TextFile& file, std::vector<RegressionCell>* cells,
                      RegressionTolerance* tolerance);

// True when `path` holds a baseline (JSON with the baseline format): what --force may replace.
bool IsBaselineFile(const std::string& path);

}  // namespace vigil::experiments
