#include "sim/waypoint_trajectory.h"

#include <cmath>

#include "core/csv.h"
#include "core/error.h"
#include "sim/euler.h"

namespace vigil::sim {

std::vector<Waypoint> ReadWaypoints(const std::string& path) {
  CsvReader r(path, 7, "t [s],x [m],y [m],z [m],yaw [rad],pitch [rad],roll [rad]");
  std::vector<Waypoint> out;
  while (r.Next()) {
    Waypoint w;
    w.t_s = r.Double(0);
    w.p_W = Eigen::Vector3d(r.Double(1), r.Double(2), r.Double(3));
    w.yaw = r.Double(4);
    w.pitch = r.Double(5);
    w.roll = r.Double(6);
    if (!out.empty() && !(w.t_s > out.back().t_s)) r.Fail("time does not increase");
    if (std::abs(w.pitch) >= 1.5) r.Fail("pitch must be within (-1.5, 1.5) rad (Euler singularity at pi/2)");
    out.push_back(w);
  }
  if (out.size() < 2)
    throw InputError(path + ": at least 2 waypoints are required, found " + std::to_string(out.size()));
  return out;
}

WaypointTrajectory::WaypointTrajectory(const std::vector<Waypoint>& waypoints) {
  constexpr double kPi = 3.14159265358979323846;
  const std::size_t n = waypoints.size();
  std::vector<double> t(n);
  std::vector<std::vector<double>> channels(6, std::vector<double>(n));
  double yaw = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Waypoint& w = waypoints[i];
    t[i] = w.t_s - waypoints.front().t_s;
    yaw = i == 0 ? w.yaw : yaw + std::remainder(w.yaw - yaw, 2.0 * kPi);  // unwrap
    const double values[6] = {w.p_W.x(), w.p_W.y(), w.p_W.z(), yaw, w.pitch, w.roll};
    for (int c = 0; c < 6; ++c) channels[static_cast<std::size_t>(c)][i] = values[c];
  }
  end_time_s_ = t.back();
  for (auto& channel : channels) splines_.emplace_back(t, std::move(channel));
}

TrajectoryState WaypointTrajectory::StateAt(double t_s) const {
  CubicSpline::Sample s[6];
  for (std::size_t c = 0; c < 6; ++c) s[c] = splines_[c].Evaluate(t_s);
  TrajectoryState x;
  x.p_W = Eigen::Vector3d(s[0].value, s[1].value, s[2].value);
  x.v_W = Eigen::Vector3d(s[0].d1, s[1].d1, s[2].d1);
  x.a_W = Eigen::Vector3d(s[0].d2, s[1].d2, s[2].d2);
  const double yaw = s[3].value, pitch = s[4].value, roll = s[5].value;
  x.q_WB = Eigen::Quaterniond(RotationFromEulerZyx(roll, pitch, yaw));
  x.w_B = EulerRatesToBodyRates(roll, pitch) * Eigen::Vector3d(s[5].d1, s[4].d1, s[3].d1);
  return x;
}

}  // namespace vigil::sim
