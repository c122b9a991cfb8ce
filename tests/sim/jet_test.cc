#include "sim/jet.h"

#include <gtest/gtest.h>

namespace vigil::sim {
namespace {

// A composite of every operation, as a function of time.
Jet Composite(double t) {
  const Jet x = Jet::Variable(t);
  const Jet a = tanh(sin(2.0 * x)) * sqrt(2.0 + cos(x)) / (1.0 + x * x);
  const Jet b = atan(0.5 * x - 1.0) - (3.0 - x) / 4.0;
  return a + b * a - atan2(1.0 + 0.3 * x, cos(x) + 2.0);
}

// Each derivative of the jet matches the central difference of the next lower one.
TEST(Jet, DerivativesMatchCentralDifferences) {
  const double h = 1e-5;
  for (double t = -2.0; t < 2.0; t += 0.37) {
    const Jet j = Composite(t), jm = Composite(t - h), jp = Composite(t + h);
    for (int k = 1; k <= 3; ++k) {
      const double fd = (jp.d[k - 1] - jm.d[k - 1]) / (2.0 * h);
      EXPECT_NEAR(j.d[k], fd, 1e-6 * (1.0 + std::abs(fd))) << "order " << k << " at t = " << t;
    }
  }
}

TEST(Jet, KnownValues) {
  const Jet s = sin(Jet::Variable(0.0));
  EXPECT_EQ(s.d, (std::array<double, 4>{0.0, 1.0, 0.0, -1.0}));
  const Jet p = Jet::Variable(2.0) * Jet::Variable(2.0) * Jet::Variable(2.0);  // t^3
  EXPECT_EQ(p.d, (std::array<double, 4>{8.0, 12.0, 12.0, 6.0}));
  EXPECT_TRUE(std::isnan(p.Derivative().d[3]));
  EXPECT_EQ(p.Derivative().d[2], 6.0);
}

}  // namespace
}  // namespace vigil::sim
