#include "core/format.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace vigil {
namespace {

TEST(Format, DoublesRoundTripBitForBit) {
  for (double v : {0.1, 1.0 / 3.0, 9.81, -1e-300, 123456789.123456789, std::nextafter(1.0, 2.0)}) {
    double back = 0.0;
    ASSERT_TRUE(ParseDouble(FormatDouble(v), &back));
    EXPECT_EQ(back, v);
  }
  EXPECT_EQ(FormatDouble(0.1), "0.1");
  EXPECT_EQ(FormatDouble(-0.0), "0");
  EXPECT_EQ(FormatFixed(1.5, 3), "1.500");
}

TEST(Format, ParsingIsStrict) {
  double d;
  int64_t i;
  EXPECT_FALSE(ParseDouble("1.0x", &d));
  EXPECT_FALSE(ParseDouble("", &d));
  EXPECT_FALSE(ParseDouble("nan", &d));
  EXPECT_FALSE(ParseDouble("inf", &d));
  EXPECT_TRUE(ParseDouble(" +2.5e3 ", &d));
  EXPECT_EQ(d, 2500.0);
  EXPECT_FALSE(ParseInt64("1.5", &i));
  EXPECT_FALSE(ParseInt64("99999999999999999999", &i));
  EXPECT_TRUE(ParseInt64("-42", &i));
  EXPECT_EQ(i, -42);
}

}  // namespace
}  // namespace vigil
