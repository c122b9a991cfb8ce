// A C2 motion through user-given timed poses (trajectory.type waypoints).
//
// File format (CSV, one '#' header line, then one row per waypoint, times strictly increasing, >= 2 rows):
//   #t [s],x [m],y [m],z [m],yaw [rad],pitch [rad],roll [rad]
// Position and ZYX Euler angles (R_WB = Rz(yaw) Ry(pitch) Rx(roll)) are each interpolated by a natural cubic
// spline in time (sim/cubic_spline.h), so p_W is C2 (acceleration continuous, zero at both ends) and the
// attitude C2; velocity, acceleration and the body rate w_B = E(roll, pitch) * Euler rates are the splines'
// exact derivatives. Time is shifted so the first waypoint is at t = 0; the model ends at the last waypoint.
// Yaw is unwrapped (a jump of more than pi between waypoints is taken the short way round). Keep |pitch| well
// below pi/2 (the Euler parameterization is singular there).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "sim/cubic_spline.h"
#include "sim/trajectory_model.h"

namespace vigil::sim {

struct Waypoint {
  double t_s = 0;
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  double yaw = 0, pitch = 0, roll = 0;  // [rad]
};

// Reads a waypoint file; InputError "file:line: reason" on a bad row, unordered times or fewer than 2 rows.
std::vector<Waypoint> ReadWaypoints(const std::string& path);

class WaypointTrajectory final : public TrajectoryModel {
 public:
  explicit WaypointTrajectory(const std::vector<Waypoint>& waypoints);

  TrajectoryState StateAt(double t_s) const override;
  double EndTime() const override { return end_time_s_; }

 private:
  // x, y, z, yaw, pitch, roll.
  std::vector<CubicSpline> splines_;
  double end_time_s_ = 0;
};

}  // namespace vigil::sim
