#include "sim/scale_misalignment.h"

#include <cmath>

namespace vigil::sim {

Eigen::Matrix3d ScaleMisalignmentMatrix(const std::vector<double>& scale,
                                        const std::vector<double>& misalignment_deg) {
  const double d = M_PI / 180.0;
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  N(1, 2) = N(2, 1) = misalignment_deg.at(0) * d;
  N(2, 0) = N(0, 2) = misalignment_deg.at(1) * d;
  N(0, 1) = N(1, 0) = misalignment_deg.at(2) * d;
  const Eigen::Vector3d s(scale.at(0), scale.at(1), scale.at(2));
  return (Eigen::Matrix3d::Identity() + Eigen::Matrix3d(s.asDiagonal())) * (Eigen::Matrix3d::Identity() + N);
}

bool IsIdentity(const ScaleMisalignmentOptions& o) {
  for (const auto* v : {&o.accel_scale, &o.gyro_scale, &o.accel_misalignment_deg, &o.gyro_misalignment_deg})
    for (const double x : *v)
      if (x != 0.0) return false;
  return true;
}

void ApplyScaleMisalignment(const ScaleMisalignmentOptions& options, ImuStream* imu) {
  if (IsIdentity(options)) return;
  const Eigen::Matrix3d M_a = ScaleMisalignmentMatrix(options.accel_scale, options.accel_misalignment_deg);
  const Eigen::Matrix3d M_g = ScaleMisalignmentMatrix(options.gyro_scale, options.gyro_misalignment_deg);
  for (ImuSample& s : *imu) {
    s.a_B = M_a * s.a_B;
    s.w_B = M_g * s.w_B;
  }
}

}  // namespace vigil::sim
