#include "sim/cubic_spline.h"

#include <algorithm>
#include <cassert>

namespace vigil::sim {

CubicSpline::CubicSpline(std::vector<double> t, std::vector<double> y)
    : t_(std::move(t)), y_(std::move(y)), m_(t_.size(), 0.0) {
  assert(t_.size() == y_.size() && t_.size() >= 2);
  const std::size_t n = t_.size();
  if (n < 3) return;  // a straight line
  // Continuity of the first derivative at the interior knots gives a tridiagonal system in m_1 .. m_{n-2}
  // (m_0 = m_{n-1} = 0), solved by the Thomas algorithm (diagonally dominant, no pivoting needed).
  std::vector<double> diag(n, 0.0), upper(n, 0.0), rhs(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = t_[i] - t_[i - 1], h1 = t_[i + 1] - t_[i];
    diag[i] = 2.0 * (h0 + h1);
    upper[i] = h1;
    rhs[i] = 6.0 * ((y_[i + 1] - y_[i]) / h1 - (y_[i] - y_[i - 1]) / h0);
    if (i > 1) {  // eliminate the sub-diagonal entry h0 with the previous row
      const double f = h0 / diag[i - 1];
      diag[i] -= f * upper[i - 1];
      rhs[i] -= f * rhs[i - 1];
    }
  }
  for (std::size_t i = n - 2; i >= 1; --i) {
    m_[i] = (rhs[i] - upper[i] * m_[i + 1]) / diag[i];
    if (i == 1) break;
  }
}

CubicSpline::Sample CubicSpline::Evaluate(double t) const {
  // Interval [t_i, t_{i+1}] containing t (the end intervals extend beyond the knots).
  const auto it = std::upper_bound(t_.begin() + 1, t_.end() - 1, t);
  const std::size_t i = static_cast<std::size_t>(it - t_.begin()) - 1;
  const double h = t_[i + 1] - t_[i];
  const double a = (t_[i + 1] - t) / h, b = (t - t_[i]) / h;  // a + b = 1
  const double m0 = m_[i], m1 = m_[i + 1];
  Sample s;
  s.value = a * y_[i] + b * y_[i + 1] + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0;
  s.d1 = (y_[i + 1] - y_[i]) / h + ((1.0 - 3.0 * a * a) * m0 + (3.0 * b * b - 1.0) * m1) * h / 6.0;
  s.d2 = a * m0 + b * m1;
  return s;
}

}  // namespace vigil::sim
