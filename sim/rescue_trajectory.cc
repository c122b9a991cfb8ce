#include "sim/rescue_trajectory.h"

#include <cmath>

#include "sim/euler.h"

namespace vigil::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Quintic smoothstep of s = (u - start) / width: 0 before, 1 after, C2.
Jet SmoothStep(const Jet& u, double start, double width) {
  const double s = (u.value() - start) / width;
  if (s <= 0.0) return Jet::Constant(0.0);
  if (s >= 1.0) return Jet::Constant(1.0);
  const Jet x = (u - start) / width;
  return x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
}

// Bump 64 s^3 (1 - s)^3 of height 1 at s = 1/2, s = (u - centre) / width + 1/2: C2 at both ends.
Jet Bump(const Jet& u, double centre, double width) {
  const double s = (u.value() - centre) / width + 0.5;
  if (s <= 0.0 || s >= 1.0) return Jet::Constant(0.0);
  const Jet x = (u - centre) / width + 0.5;
  const Jet y = 1.0 - x;
  return 64.0 * (x * x * x) * (y * y * y);
}

}  // namespace

Jet RescueTrajectory::RampHeight(const Jet& u) {
  // Straights are centred on u = 0, pi/2, pi, 3 pi/2 (the first one is entered at u = -pi/4, i.e. at the end
  // of the previous loop; every feature lies inside (0, 2 pi) and the profile returns to 0 before the end).
  return 0.4 * (SmoothStep(u, 0.05, 0.5) - SmoothStep(u, 0.5 * kPi - 0.25, 0.5));
}

Jet RescueTrajectory::StepHeight(const Jet& u) {
  // Platform on the third straight (about 6.6 m per radian there): steps 0.03 rad ~ 20 cm long.
  Jet z = 0.03 * (SmoothStep(u, kPi - 0.2, 0.03) - SmoothStep(u, kPi + 0.2, 0.03));
  // Bumps on the fourth straight (about 9.9 m per radian there): 0.04 rad ~ 40 cm long.
  for (const double centre : {1.5 * kPi - 0.3, 1.5 * kPi, 1.5 * kPi + 0.3})
    z = z + 0.01 * Bump(u, centre, 0.04);
  return z;
}

Jet RescueTrajectory::BankAngle(const Jet& u) {
  return 0.06 * (SmoothStep(u, 0.5 * kPi + 0.3, 0.15) - SmoothStep(u, 0.75 * kPi - 0.15, 0.15));
}

TrajectoryState RescueTrajectory::StateAt(double t_s) const {
  constexpr double w = 2.0 * kPi / kLoopPeriodS;
  const Jet t = Jet::Variable(t_s);
  const Jet phi = w * t - kSpeedEqualization * sin(4.0 * w * t);
  const double beta = kCornerSharpness, norm = 1.0 / std::tanh(beta);
  const Jet x = kHalfLengthM * norm * tanh(beta * cos(phi));
  const Jet y = kHalfWidthM * norm * tanh(beta * sin(phi));
  Jet u = phi;  // loop angle in [0, 2 pi)
  u.d[0] -= 2.0 * kPi * std::floor(phi.value() / (2.0 * kPi));
  const Jet ramp = RampHeight(u);
  const Jet z = kBodyHeightM + ramp + StepHeight(u);

  // Heading along the horizontal velocity; pitch follows the ramps only (the wheelbase rides over the short
  // steps and bumps, which move the body vertically).
  const Jet vx = x.Derivative(), vy = y.Derivative();
  const Jet yaw = atan2(vy, vx);
  const Jet pitch = -atan(ramp.Derivative() / sqrt(vx * vx + vy * vy));
  const Jet roll = BankAngle(u);

  TrajectoryState s;
  s.p_W = Eigen::Vector3d(x.d[0], y.d[0], z.d[0]);
  s.v_W = Eigen::Vector3d(x.d[1], y.d[1], z.d[1]);
  s.a_W = Eigen::Vector3d(x.d[2], y.d[2], z.d[2]);
  s.q_WB = Eigen::Quaterniond(RotationFromEulerZyx(roll.d[0], pitch.d[0], yaw.d[0]));
  s.w_B = EulerRatesToBodyRates(roll.d[0], pitch.d[0]) * Eigen::Vector3d(roll.d[1], pitch.d[1], yaw.d[1]);
  return s;
}

}  // namespace vigil::sim
