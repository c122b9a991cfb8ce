// A ground robot on a rescue training course: a rounded-rectangle loop with ramps, a raised platform (steps),
// bumps and a banked stretch.
//
// Geometry (all pieces analytic and at least C2, derivatives exact through sim/jet.h):
// - Plan view: the loop parameter phi(t) = w t - c sin(4 w t) drives the rounded rectangle
//     x = A tanh(beta cos phi) / tanh(beta),   y = B tanh(beta sin phi) / tanh(beta)
//   with A = 6 m, B = 4 m, beta = 1.5 (straights centred on phi = 0, pi/2, pi, 3 pi/2, corners in between)
//   and c = 0.1, which slows the loop parameter on the straights and speeds it up in the corners (speed
//   between about 0.7 and 1.4 m/s, mean 1 m/s). w = 2 pi / kLoopPeriodS: one loop (about 36 m) in 36 s,
//   starting at (A, 0) and heading +y (counter-clockwise).
// - Height of the IMU: kBodyHeightM above a course profile of the loop angle u = phi mod 2 pi, built from
//   quintic smoothsteps S(s) = 6 s^5 - 15 s^4 + 10 s^3 (C2) and bumps 64 s^3 (1 - s)^3 (C2):
//     a 0.4 m ramp up along the first straight and down along the second (about 2.5 m long, up to 16 deg);
//     a 3 cm platform on the third straight entered and left by 20 cm long steps; three 1 cm bumps 40 cm long
//     on the fourth. Steps and bumps give vertical acceleration peaks of about 2-4 m/s^2 lasting tens of ms:
//     legitimate motion that a glitch detector must not flag.
// - Attitude: yaw = heading of the horizontal velocity; pitch = -atan(ramp climb rate / horizontal speed)
//   (x_B along the ramp; the wheelbase rides over steps and bumps, which only move the body vertically);
//   roll rises smoothly to 0.06 rad and back on a banked stretch of the second straight.
//   R_WB = Rz(yaw) Ry(pitch) Rx(roll).
// The default camera looks along -x_B, i.e. backwards along the course: use landmarks on the walls of the
// hall around the course (landmarks.layout random), as configs/rescue.yaml does.
#pragma once

#include "sim/jet.h"
#include "sim/trajectory_model.h"

namespace vigil::sim {

class RescueTrajectory final : public TrajectoryModel {
 public:
  static constexpr double kHalfLengthM = 6.0;        // A
  static constexpr double kHalfWidthM = 4.0;         // B
  static constexpr double kCornerSharpness = 1.5;    // beta
  static constexpr double kSpeedEqualization = 0.1;  // c
  static constexpr double kLoopPeriodS = 36.0;
  static constexpr double kBodyHeightM = 0.3;

  TrajectoryState StateAt(double t_s) const override;

  // Profile of the course at loop angle u in [0, 2 pi), as jets: the ramps (which also pitch the robot), the
  // steps and bumps (vertical motion only) and the bank (roll) angle.
  static Jet RampHeight(const Jet& u);
  static Jet StepHeight(const Jet& u);
  static Jet BankAngle(const Jet& u);
};

}  // namespace vigil::sim
