#include "evaluation/statistics.h"

#include <algorithm>
#include <cmath>

#include "evaluation/metrics_access.h"

namespace vigil::evaluation {

ErrorStatistics ComputeStatistics(std::vector<double> values) {
  ErrorStatistics s;
  s.n = static_cast<int64_t>(values.size());
  if (values.empty()) return s;
  const double n = static_cast<double>(values.size());
  double sum = 0.0, sum_sq = 0.0;
  for (double v : values) sum += v, sum_sq += v * v;
  s.mean = sum / n;
  s.rmse = std::sqrt(sum_sq / n);
  double var = 0.0;
  for (double v : values) var += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(var / n);
  std::sort(values.begin(), values.end());
  s.min = values.front();
  s.max = values.back();
  const std::size_t mid = values.size() / 2;
  s.median = values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
  return s;
}

nlohmann::json StatisticsJson(const ErrorStatistics& stats) {
  return {{"rmse", NumberOrNull(stats.rmse)},
          {"mean", NumberOrNull(stats.mean)},
          {"median", NumberOrNull(stats.median)},
          {"std", NumberOrNull(stats.std)},
          {"min", NumberOrNull(stats.min)},
          {"max", NumberOrNull(stats.max)},
          {"n", stats.n}};
}

}  // namespace vigil::evaluation
