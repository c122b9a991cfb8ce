#include "sim/cubic_spline.h"

#include <cmath>

#include <gtest/gtest.h>

namespace vigil::sim {
namespace {

const std::vector<double> kT = {0.0, 0.5, 1.7, 2.0, 3.5, 4.0};
const std::vector<double> kY = {1.0, -2.0, 0.3, 0.8, 5.0, 4.5};

TEST(CubicSpline, InterpolatesIsC2AndNatural) {
  const CubicSpline s(kT, kY);
  for (std::size_t i = 0; i < kT.size(); ++i) EXPECT_NEAR(s.Evaluate(kT[i]).value, kY[i], 1e-12);
  const double e = 1e-9;
  for (std::size_t i = 1; i + 1 < kT.size(); ++i) {
    const auto l = s.Evaluate(kT[i] - e), r = s.Evaluate(kT[i] + e);
    EXPECT_NEAR(l.d1, r.d1, 1e-6) << "knot " << i;
    EXPECT_NEAR(l.d2, r.d2, 1e-6) << "knot " << i;
  }
  EXPECT_NEAR(s.Evaluate(kT.front()).d2, 0.0, 1e-12);
  EXPECT_NEAR(s.Evaluate(kT.back()).d2, 0.0, 1e-12);
}

TEST(CubicSpline, DerivativesMatchCentralDifferences) {
  const CubicSpline s(kT, kY);
  const double h = 1e-6;
  for (double t = 0.05; t < 4.0; t += 0.113) {
    const auto c = s.Evaluate(t), m = s.Evaluate(t - h), p = s.Evaluate(t + h);
    EXPECT_NEAR(c.d1, (p.value - m.value) / (2 * h), 1e-6);
    EXPECT_NEAR(c.d2, (p.d1 - m.d1) / (2 * h), 1e-5);
  }
}

TEST(CubicSpline, ReproducesStraightLines) {
  std::vector<double> y;
  for (double t : kT) y.push_back(3.0 - 2.0 * t);
  const CubicSpline s(kT, y);
  for (double t = 0.0; t <= 4.0; t += 0.25) {
    const auto v = s.Evaluate(t);
    EXPECT_NEAR(v.value, 3.0 - 2.0 * t, 1e-12);
    EXPECT_NEAR(v.d1, -2.0, 1e-12);
    EXPECT_NEAR(v.d2, 0.0, 1e-12);
  }
  const CubicSpline two({0.0, 2.0}, {1.0, 5.0});
  EXPECT_NEAR(two.Evaluate(0.5).value, 2.0, 1e-15);
}

}  // namespace
}  // namespace vigil::sim
