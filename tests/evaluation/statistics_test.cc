#include "evaluation/statistics.h"

#include <cmath>

#include <gtest/gtest.h>

namespace vigil::evaluation {
namespace {

TEST(Statistics, HandComputed) {
  const ErrorStatistics s = ComputeStatistics({4.0, 1.0, 3.0, 2.0});
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(7.5));
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(1.25));  // population: divided by n
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 4.0);
  EXPECT_EQ(s.n, 4);
  EXPECT_DOUBLE_EQ(ComputeStatistics({5.0, 1.0, 3.0}).median, 3.0);
}

TEST(Statistics, EmptyIsNullInJson) {
  const ErrorStatistics s = ComputeStatistics({});
  EXPECT_EQ(s.n, 0);
  EXPECT_TRUE(std::isnan(s.rmse));
  const nlohmann::json j = StatisticsJson(s);
  EXPECT_TRUE(j["rmse"].is_null());
  EXPECT_EQ(j["n"], 0);
  for (const char* key : {"rmse", "mean", "median", "std", "min", "max", "n"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(StatisticsJson(ComputeStatistics({2.0}))["rmse"], 2.0);
}

}  // namespace
}  // namespace vigil::evaluation
