#include "experiments/sweeps/regression_baseline.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/error.h"
#include "core/output.h"
#include "experiments/runs/json_document.h"

namespace vigil::experiments {

bool IsRegressionMetric(const std::string& m) {
  return m == "ate_rmse_m" || m == "re_trans_m" || m == "re_yaw_deg";
}

bool IsBaselineFile(const std::string& path) {
  try {
    const JsonDocument doc(path, ReadFile(path));
    return doc.root().is_object() && doc.root().value("format", "") == kBaselineFormat;
  } catch (const InputError&) {
    return false;
  }
}

void ReadBaseline(const std::string& path, std::vector<RegressionCell>* cells,
                  RegressionTolerance* tolerance) {
  ReadBaselineText({path, ReadFile(path)}, cells, tolerance);
}

void ReadBaselineText(const TextFile& file, std::vector<RegressionCell>* cells,
                      RegressionTolerance* tolerance) {
  const JsonDocument doc(file.path, file.text);
  const nlohmann::json& j = doc.root();
  // The value at `pointer` of the expected JSON type (`what` says which), else a located error.
  auto at = [&](const std::string& pointer, bool (nlohmann::json::*is)() const noexcept,
                const char* what) -> const nlohmann::json& {
    const nlohmann::json::json_pointer p(pointer);
    if (!j.contains(p)) doc.Fail(pointer, std::string("missing (expected ") + what + ")");
    const nlohmann::json& v = j.at(p);
    if (!(v.*is)()) doc.Fail(pointer, std::string("expected ") + what + ", got " + v.type_name());
    return v;
  };
  auto number = [&](const std::string& pointer) {
    const double v = at(pointer, &nlohmann::json::is_number, "a number").get<double>();
    if (!std::isfinite(v) || v < 0) doc.Fail(pointer, "must be a finite number >= 0");
    return v;
  };
  if (!j.is_object()) doc.Fail("", std::string("expected a JSON object, got ") + j.type_name());
  if (at("/format", &nlohmann::json::is_string, "a string").get<std::string>() != kBaselineFormat)
    doc.Fail("/format", std::string("expected \"") + kBaselineFormat + "\"");
  for (const auto& [key, value] : j.items())
    if (key != "format" && key != "sweep" && key != "tolerance" && key != "cells")
      doc.Fail("/" + PointerToken(key), "unknown key");
  if (j.contains("sweep")) at("/sweep", &nlohmann::json::is_string, "a string");
  at("/tolerance", &nlohmann::json::is_object, "an object");
  tolerance->relative = number("/tolerance/relative");
  tolerance->absolute.clear();
  for (const auto& [metric, value] :
       at("/tolerance/absolute", &nlohmann::json::is_object, "an object").items()) {
    if (!IsRegressionMetric(metric))
      doc.Fail("/tolerance/absolute/" + PointerToken(metric), "unknown metric");
    tolerance->absolute[metric] = number("/tolerance/absolute/" + metric);
  }
  const nlohmann::json& list = at("/cells", &nlohmann::json::is_array, "an array of cells");
  // A gate that compares nothing passes whatever the sweep did: refuse it.
  if (list.empty()) doc.Fail("/cells", "no cells (a baseline must compare at least one)");
  cells->clear();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string p = "/cells/" + std::to_string(i);
    at(p, &nlohmann::json::is_object, "an object {metric, cell, value, failed}");
    for (const auto& [key, value] : list[i].items())
      if (key != "metric" && key != "cell" && key != "value" && key != "failed")
        doc.Fail(p + "/" + PointerToken(key), "unknown key");
    RegressionCell cell;
    cell.metric = at(p + "/metric", &nlohmann::json::is_string, "a string").get<std::string>();
    if (!IsRegressionMetric(cell.metric))
      doc.Fail(p + "/metric", "expected ate_rmse_m, re_trans_m or re_yaw_deg, got \"" + cell.metric + "\"");
    cell.cell = at(p + "/cell", &nlohmann::json::is_string, "a string").get<std::string>();
    if (cell.cell.empty()) doc.Fail(p + "/cell", "empty cell name");
    const nlohmann::json& failed = at(p + "/failed", &nlohmann::json::is_number_integer, "an integer");
    if (failed.is_number_unsigned() ? failed.get<uint64_t>() > 1000000000 : failed.get<int64_t>() < 0)
      doc.Fail(p + "/failed", "must be an integer in [0, 1e9]");
    cell.failed = failed.get<long>();
    const std::string value = p + "/value";
    if (!list[i].contains("value"))
      doc.Fail(value, "missing (expected a number, or null when every run failed)");
    // null records a cell whose runs all failed; with no failed run it would disable the cell's check.
    if (list[i]["value"].is_null()) {
      if (cell.failed == 0) doc.Fail(value, "null but no run failed (a cell with runs has a value)");
      cell.value = std::numeric_limits<double>::quiet_NaN();
    } else {
      cell.value = number(value);
    }
    for (const RegressionCell& earlier : *cells)
      if (earlier.metric == cell.metric && earlier.cell == cell.cell)
        doc.Fail(p, "duplicate cell " + cell.cell);
    cells->push_back(cell);
  }
}

}  // namespace vigil::experiments
