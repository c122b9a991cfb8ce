// Summary statistics of a list of errors, as rpg_trajectory_evaluation reports them.
//
// rmse = sqrt(mean of squares), mean, median (mean of the two middle values for an even count), std
// (population, i.e. divided by n), min, max and n. With no value every statistic is NaN (written as null in
// JSON) and n = 0.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

namespace vigil::evaluation {

struct ErrorStatistics {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double rmse = kNaN, mean = kNaN, median = kNaN, std = kNaN, min = kNaN, max = kNaN;
  int64_t n = 0;
};

ErrorStatistics ComputeStatistics(std::vector<double> values);

// {"rmse": .., "mean": .., "median": .., "std": .., "min": .., "max": .., "n": ..} (NaN as null).
nlohmann::json StatisticsJson(const ErrorStatistics& stats);

}  // namespace vigil::evaluation
