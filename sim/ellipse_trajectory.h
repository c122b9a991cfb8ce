// The reference simulator's motion (HeYijia/vio_data_simulation): an ellipse with a vertical wave.
//
//   p_W(t) = (15 cos(K t) + 5, 20 sin(K t) + 5, sin(K1 K t) + 5),   K = pi / 10, K1 = 10
//   (roll, pitch, yaw)(t) = (0.1 cos t, 0.2 sin t, K t),            R_WB = Rz(yaw) Ry(pitch) Rx(roll)
//
// One loop takes 2 pi / K = 20 s and is about 119 m long. Yaw follows the angle on the ellipse, so -x_B (the
// default camera axis) points roughly toward the ellipse's centre (5, 5), where the house landmarks stand.
// Velocity, acceleration and body rates are the exact derivatives of these expressions.
#pragma once

#include "sim/trajectory_model.h"

namespace vigil::sim {

class EllipseTrajectory final : public TrajectoryModel {
 public:
  static constexpr double kK = 3.14159265358979323846 / 10.0;  // angular rate on the ellipse [rad/s]
  static constexpr double kK1 = 10.0;                          // vertical waves per loop

  TrajectoryState StateAt(double t_s) const override;
};

}  // namespace vigil::sim
