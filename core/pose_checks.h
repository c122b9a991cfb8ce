// The rules every reader of recorded or estimated poses applies to a row, written once: a quaternion is a
// rotation only when its norm is within kUnitQuaternionTolerance of 1 (a 3x or a zero quaternion is a broken
// writer, not a rounding), and consecutive rows of a trajectory never turn by more than a quarter turn (a
// flipped row, and beyond it the interpolation between rows is ambiguous).
#pragma once

#include <string>

#include <Eigen/Geometry>

namespace vigil {

inline constexpr double kUnitQuaternionTolerance = 1e-3;
inline constexpr double kMaxPoseRotationStep_rad = 1.5707963267948966;

// "" when |q| is within kUnitQuaternionTolerance of 1, else "quaternion is not unit (norm N)".
std::string QuaternionNormProblem(const Eigen::Quaterniond& q);

// "" when q_prev -> q turns by at most kMaxPoseRotationStep_rad, else "orientation jumps A deg since the
// previous row (more than 90 deg between two poses)". Both unit.
std::string RotationStepProblem(const Eigen::Quaterniond& q_prev, const Eigen::Quaterniond& q);

}  // namespace vigil
