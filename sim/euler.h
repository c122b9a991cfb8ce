// ZYX Euler angles (roll about x, pitch about y, yaw about z) as used by the reference simulator.
//
// R_WB = Rz(yaw) Ry(pitch) Rx(roll). The body angular rate follows from the Euler rates through
//   w_B = E(roll, pitch) [roll_dot, pitch_dot, yaw_dot]^T,
//   E = [[1, 0, -sin(pitch)], [0, cos(roll), sin(roll) cos(pitch)], [0, -sin(roll), cos(roll) cos(pitch)]].
#pragma once

#include <Eigen/Core>

namespace vigil::sim {

// R_WB of ZYX Euler angles [rad].
Eigen::Matrix3d RotationFromEulerZyx(double roll, double pitch, double yaw);

// The matrix E above: body rate = E * Euler rates.
Eigen::Matrix3d EulerRatesToBodyRates(double roll, double pitch);

}  // namespace vigil::sim
