#include "sim/ellipse_trajectory.h"

#include <cmath>

#include "sim/euler.h"

namespace vigil::sim {

TrajectoryState EllipseTrajectory::StateAt(double t) const {
  constexpr double K = kK, Kz = kK1 * kK;
  const double c = std::cos(K * t), s = std::sin(K * t), cz = std::cos(Kz * t), sz = std::sin(Kz * t);

  TrajectoryState x;
  x.p_W = Eigen::Vector3d(15.0 * c + 5.0, 20.0 * s + 5.0, sz + 5.0);
  x.v_W = Eigen::Vector3d(-15.0 * K * s, 20.0 * K * c, Kz * cz);
  x.a_W = Eigen::Vector3d(-15.0 * K * K * c, -20.0 * K * K * s, -Kz * Kz * sz);

  const double roll = 0.1 * std::cos(t), pitch = 0.2 * std::sin(t), yaw = K * t;
  const Eigen::Vector3d euler_rates(-0.1 * std::sin(t), 0.2 * std::cos(t), K);
  x.q_WB = Eigen::Quaterniond(RotationFromEulerZyx(roll, pitch, yaw));
  x.w_B = EulerRatesToBodyRates(roll, pitch) * euler_rates;
  return x;
}

}  // namespace vigil::sim
