#include "sim/euler.h"

#include <cmath>

#include <Eigen/Geometry>

namespace vigil::sim {

Eigen::Matrix3d RotationFromEulerZyx(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Matrix3d EulerRatesToBodyRates(double roll, double pitch) {
  const double sr = std::sin(roll), cr = std::cos(roll), sp = std::sin(pitch), cp = std::cos(pitch);
  Eigen::Matrix3d E;
  E << 1.0, 0.0, -sp,    //
      0.0, cr, sr * cp,  //
      0.0, -sr, cr * cp;
  return E;
}

}  // namespace vigil::sim
