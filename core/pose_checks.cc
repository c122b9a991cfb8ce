#include "core/pose_checks.h"

#include <cmath>

#include "core/format.h"
#include "core/so3.h"

namespace vigil {

std::string QuaternionNormProblem(const Eigen::Quaterniond& q) {
  const double norm = q.norm();
  if (std::abs(norm - 1.0) <= kUnitQuaternionTolerance) return "";
  return "quaternion is not unit (norm " + FormatDouble(norm) + ")";
}

std::string RotationStepProblem(const Eigen::Quaterniond& q_prev, const Eigen::Quaterniond& q) {
  const double angle = AngleOf(q_prev.conjugate() * q);
  if (angle <= kMaxPoseRotationStep_rad) return "";
  return "orientation jumps " + FormatDouble(angle * 180.0 / M_PI) +
         " deg since the previous row (more than 90 deg between two poses)";
}

}  // namespace vigil
