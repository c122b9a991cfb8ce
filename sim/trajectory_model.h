// Motion models of the simulator: the body state as a smooth function of time.
//
// A TrajectoryModel gives, at any time t in [0, EndTime()], the pose of the body frame B in the world frame W
// and its exact time derivatives: every model is built from analytic expressions differentiated exactly (by
// hand or with sim/jet.h), never by finite differences, so the IMU synthesized from them integrates back to
// the trajectory up to the integrator's own error.
//
// Frames: W is z up (gravity along -z), B is the IMU frame. q_WB rotates B vectors into W; w_B is the angular
// velocity of B relative to W expressed in B (what an ideal gyro reads).
#pragma once

#include <limits>
#include <memory>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sim/sim_options.h"

namespace vigil::sim {

// Kinematic state of the body at one instant.
struct TrajectoryState {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();  // position [m]
  Eigen::Vector3d v_W = Eigen::Vector3d::Zero();  // velocity [m/s]
  Eigen::Vector3d a_W = Eigen::Vector3d::Zero();  // acceleration (not specific force) [m/s^2]
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  Eigen::Vector3d w_B = Eigen::Vector3d::Zero();  // body angular rate [rad/s]
};

class TrajectoryModel {
 public:
  virtual ~TrajectoryModel() = default;
  // State at time t_s (seconds from the start of the simulation); t_s in [0, EndTime()].
  virtual TrajectoryState StateAt(double t_s) const = 0;
  // Last time at which the model is defined [s] (infinite for periodic models).
  virtual double EndTime() const { return std::numeric_limits<double>::infinity(); }
};

// Builds the model selected by `options.type`. Throws InputError (naming trajectory.* keys) when the model's
// input is bad, e.g. an unreadable or malformed waypoints file, and (naming duration_s) when the model ends
// before `duration_s`: a recording's span is checked before its spline is fitted.
std::unique_ptr<TrajectoryModel> MakeTrajectoryModel(const TrajectoryOptions& options,
                                                     double duration_s = 0.0);

}  // namespace vigil::sim
