// Natural cubic interpolating spline of one scalar function of time, with exact derivatives.
//
// Through knots (t_i, y_i), t strictly increasing, at least 2 knots: a piecewise cubic that is C2,
// interpolates every knot and has zero second derivative at both ends (natural boundary). Outside [t_0, t_n]
// it continues the end cubics (callers stay inside).
#pragma once

#include <vector>

namespace vigil::sim {

class CubicSpline {
 public:
  // Value and first two derivatives at one time.
  struct Sample {
    double value = 0, d1 = 0, d2 = 0;
  };

  CubicSpline(std::vector<double> t, std::vector<double> y);

  Sample Evaluate(double t) const;

 private:
  std::vector<double> t_, y_;
  std::vector<double> m_;  // second derivatives at the knots
};

}  // namespace vigil::sim
