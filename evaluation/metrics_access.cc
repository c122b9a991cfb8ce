#include "evaluation/metrics_access.h"

#include <cmath>
#include <limits>
#include <string>

namespace vigil::evaluation {

nlohmann::json NumberOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

double MetricNumber(const nlohmann::json& metrics, std::initializer_list<std::string_view> path) {
  const nlohmann::json* node = &metrics;
  for (std::string_view key : path) {
    if (!node->is_object()) return std::numeric_limits<double>::quiet_NaN();
    const auto it = node->find(std::string(key));
    if (it == node->end()) return std::numeric_limits<double>::quiet_NaN();
    node = &*it;
  }
  return node->is_number() ? node->get<double>() : std::numeric_limits<double>::quiet_NaN();
}

const nlohmann::json* RelativeEntry(const nlohmann::json& metrics, double distance_m) {
  const auto it = metrics.find("relative");
  if (it == metrics.end() || !it->is_array()) return nullptr;
  for (const auto& entry : *it)
    if (std::abs(MetricNumber(entry, {"distance_m"}) - distance_m) <= 1e-9) return &entry;
  return nullptr;
}

std::string MetricText(const nlohmann::json& metrics, std::string_view key) {
  const auto it = metrics.find(std::string(key));
  return it != metrics.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace vigil::evaluation
