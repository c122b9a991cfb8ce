#include "plots/ticks.h"

#include <gtest/gtest.h>

namespace vigil::plots {
namespace {

TEST(Ticks, NiceStepsCoverTheRange) {
  const Ticks t = NiceTicks(0.0, 1.0, 5);
  EXPECT_DOUBLE_EQ(t.step, 0.2);
  ASSERT_EQ(t.values.size(), 6u);
  EXPECT_DOUBLE_EQ(t.values.front(), 0.0);
  EXPECT_DOUBLE_EQ(t.values.back(), 1.0);
  const Ticks u = NiceTicks(-3.3, 47.0, 6);
  EXPECT_DOUBLE_EQ(u.step, 10.0);
  EXPECT_DOUBLE_EQ(u.values.front(), 0.0);
  EXPECT_DOUBLE_EQ(u.values.back(), 40.0);
  const Ticks v = NiceTicks(0.0, 1.1, 5);
  EXPECT_DOUBLE_EQ(v.step, 0.25);
  EXPECT_TRUE(NiceTicks(1.0, 1.0, 5).values.empty());
}

TEST(Ticks, LabelsUseTheStepsDecimals) {
  EXPECT_EQ(FormatTick(0.5, 0.25), "0.50");
  EXPECT_EQ(FormatTick(0.25, 0.25), "0.25");
  EXPECT_EQ(FormatTick(20.0, 10.0), "20");
  EXPECT_EQ(FormatTick(0.4, 0.2), "0.4");
  EXPECT_EQ(FormatTick(-1e-17, 0.1), "0.0");
  EXPECT_EQ(FormatTick(2.5, 2.5), "2.5");
  EXPECT_EQ(FormatTick(2e7, 1e7), "2e+07");
}

TEST(Ticks, PadRangeMakesEmptyRangesUsable) {
  double lo = 3.0, hi = 3.0;
  PadRange(&lo, &hi, 0.0);
  EXPECT_LT(lo, 3.0);
  EXPECT_GT(hi, 3.0);
  lo = 0.0;
  hi = 10.0;
  PadRange(&lo, &hi, 0.1);
  EXPECT_DOUBLE_EQ(lo, -1.0);
  EXPECT_DOUBLE_EQ(hi, 11.0);
}

}  // namespace
}  // namespace vigil::plots
