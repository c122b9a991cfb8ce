// Truncated Taylor jets in one variable (time): a value with its first three derivatives.
//
// A motion model written with Jet arithmetic gets exact derivatives (to rounding) of any smooth expression:
// start from Jet::Variable(t) and every operation applies the product / quotient / chain rule up to third
// order. Third order is what a position needs so that velocity, acceleration and the heading of the velocity
// (and its rate) all come out exact. Derivative() drops one order; the lost top derivative becomes NaN so a
// misuse cannot pass silently.
#pragma once

#include <array>
#include <cmath>
#include <limits>

namespace vigil::sim {

struct Jet {
  std::array<double, 4> d{};  // d[0] value, d[1..3] derivatives d^k/dt^k

  static Jet Constant(double c) { return {{c, 0.0, 0.0, 0.0}}; }
  static Jet Variable(double t) { return {{t, 1.0, 0.0, 0.0}}; }

  double value() const { return d[0]; }
  // The jet of the derivative (one order less: its third derivative is unknown, NaN).
  Jet Derivative() const { return {{d[1], d[2], d[3], std::numeric_limits<double>::quiet_NaN()}}; }
};

// f(g) for a scalar function with derivatives f0..f3 at g's value (Faa di Bruno up to third order).
inline Jet Chain(const Jet& g, double f0, double f1, double f2, double f3) {
  const double g1 = g.d[1], g2 = g.d[2], g3 = g.d[3];
  return {{f0, f1 * g1, f2 * g1 * g1 + f1 * g2, f3 * g1 * g1 * g1 + 3.0 * f2 * g1 * g2 + f1 * g3}};
}

inline Jet operator+(const Jet& a, const Jet& b) {
  return {{a.d[0] + b.d[0], a.d[1] + b.d[1], a.d[2] + b.d[2], a.d[3] + b.d[3]}};
}
inline Jet operator-(const Jet& a, const Jet& b) {
  return {{a.d[0] - b.d[0], a.d[1] - b.d[1], a.d[2] - b.d[2], a.d[3] - b.d[3]}};
}
inline Jet operator-(const Jet& a) { return {{-a.d[0], -a.d[1], -a.d[2], -a.d[3]}}; }
inline Jet operator+(const Jet& a, double c) { return {{a.d[0] + c, a.d[1], a.d[2], a.d[3]}}; }
inline Jet operator+(double c, const Jet& a) { return a + c; }
inline Jet operator-(const Jet& a, double c) { return a + (-c); }
inline Jet operator-(double c, const Jet& a) { return -a + c; }
inline Jet operator*(const Jet& a, double c) { return {{a.d[0] * c, a.d[1] * c, a.d[2] * c, a.d[3] * c}}; }
inline Jet operator*(double c, const Jet& a) { return a * c; }
inline Jet operator/(const Jet& a, double c) { return a * (1.0 / c); }
inline Jet operator*(const Jet& a, const Jet& b) {  // Leibniz rule
  const auto &x = a.d, &y = b.d;
  return {{x[0] * y[0], x[1] * y[0] + x[0] * y[1], x[2] * y[0] + 2.0 * x[1] * y[1] + x[0] * y[2],
           x[3] * y[0] + 3.0 * x[2] * y[1] + 3.0 * x[1] * y[2] + x[0] * y[3]}};
}
inline Jet Inverse(const Jet& a) {
  const double r = 1.0 / a.d[0];
  return Chain(a, r, -r * r, 2.0 * r * r * r, -6.0 * r * r * r * r);
}
inline Jet operator/(const Jet& a, const Jet& b) { return a * Inverse(b); }

inline Jet sin(const Jet& a) {
  const double s = std::sin(a.d[0]), c = std::cos(a.d[0]);
  return Chain(a, s, c, -s, -c);
}
inline Jet cos(const Jet& a) {
  const double s = std::sin(a.d[0]), c = std::cos(a.d[0]);
  return Chain(a, c, -s, -c, s);
}
inline Jet tanh(const Jet& a) {
  const double t = std::tanh(a.d[0]), f1 = 1.0 - t * t;
  return Chain(a, t, f1, -2.0 * t * f1, f1 * (6.0 * t * t - 2.0));
}
inline Jet sqrt(const Jet& a) {
  const double s = std::sqrt(a.d[0]);
  return Chain(a, s, 0.5 / s, -0.25 / (s * a.d[0]), 0.375 / (s * a.d[0] * a.d[0]));
}
inline Jet atan(const Jet& a) {
  const double x = a.d[0], q = 1.0 / (1.0 + x * x);
  return Chain(a, std::atan(x), q, -2.0 * x * q * q, (6.0 * x * x - 2.0) * q * q * q);
}
// Angle of the vector (x, y), continuous derivatives (x, y) != 0: theta' = (x y' - y x') / (x^2 + y^2).
inline Jet atan2(const Jet& y, const Jet& x) {
  const Jet rate = (x * y.Derivative() - y * x.Derivative()) / (x * x + y * y);
  return {{std::atan2(y.d[0], x.d[0]), rate.d[0], rate.d[1], rate.d[2]}};
}

}  // namespace vigil::sim
