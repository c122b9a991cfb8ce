// Reading numbers out of a run's metrics.json (docs/formats.md) without trusting its shape: a missing key, a
// null or a non-number reads as NaN, so a failed run (which has no "ate") simply has no values.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace vigil::evaluation {

// metrics["a"]["b"]... as a double; NaN when absent or not a number.
double MetricNumber(const nlohmann::json& metrics, std::initializer_list<std::string_view> path);

// The entry of metrics["relative"] whose distance_m equals `distance_m` (within 1e-9); null when none.
const nlohmann::json* RelativeEntry(const nlohmann::json& metrics, double distance_m);

// The writing side: a finite number, or null (JSON has no NaN or infinity; MetricNumber reads null as NaN).
nlohmann::json NumberOrNull(double v);

// metrics["status"] or "" (and "failure_reason").
std::string MetricText(const nlohmann::json& metrics, std::string_view key);

}  // namespace vigil::evaluation
