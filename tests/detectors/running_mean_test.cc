#include "detectors/running_mean.h"

#include <gtest/gtest.h>

namespace vigil::detectors {
namespace {

TEST(RunningMean, AveragesTheLastNValues) {
  RunningMean mean(3);
  EXPECT_TRUE(mean.empty());
  mean.Add(1.0);
  EXPECT_DOUBLE_EQ(mean.Mean(), 1.0);
  mean.Add(2.0);
  mean.Add(6.0);
  EXPECT_EQ(mean.size(), 3);
  EXPECT_DOUBLE_EQ(mean.Mean(), 3.0);
  mean.Add(10.0);  // 1 leaves
  EXPECT_EQ(mean.size(), 3);
  EXPECT_DOUBLE_EQ(mean.Mean(), 6.0);
  mean.Clear();
  EXPECT_TRUE(mean.empty());
  mean.Add(-4.0);
  EXPECT_DOUBLE_EQ(mean.Mean(), -4.0);
}

}  // namespace
}  // namespace vigil::detectors
