#include "core/camera.h"

#include <cmath>

namespace vigil {

std::string CameraModel::Validate() const {
  if (T_BC.size() != 16)
    return "T_BC: expected 16 numbers (4x4 row-major), got " + std::to_string(T_BC.size());
  const Eigen::Matrix3d R = R_BC();
  if ((R * R.transpose() - Eigen::Matrix3d::Identity()).norm() > 1e-6 || R.determinant() < 0.0)
    return "T_BC: rotation part is not a proper rotation (orthonormal, det +1)";
  if (T_BC[12] != 0.0 || T_BC[13] != 0.0 || T_BC[14] != 0.0 || T_BC[15] != 1.0)
    return "T_BC: last row must be 0 0 0 1";
  if (distortion.size() != 4)
    return "distortion: expected 4 numbers (k1, k2, p1, p2), got " + std::to_string(distortion.size());
  for (double k : distortion)
    if (!std::isfinite(k)) return "distortion: coefficients must be finite";
  return "";
}

Eigen::Matrix3d CameraModel::R_BC() const {
  Eigen::Matrix3d R;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R(r, c) = T_BC[4 * r + c];
  return R;
}

Eigen::Vector3d CameraModel::p_BC() const { return Eigen::Vector3d(T_BC[3], T_BC[7], T_BC[11]); }

Eigen::Isometry3d CameraModel::T_BC_iso() const {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R_BC();
  T.translation() = p_BC();
  return T;
}

bool CameraModel::InImage(const Eigen::Vector2d& uv_px) const {
  return uv_px.x() >= 0.0 && uv_px.x() < width && uv_px.y() >= 0.0 && uv_px.y() < height;
}

bool CameraModel::Project(const Eigen::Vector3d& p_C, Eigen::Vector2d* uv_px, double min_depth) const {
  if (!(p_C.z() > min_depth)) return false;
  const Eigen::Vector2d uv(fx * p_C.x() / p_C.z() + cx, fy * p_C.y() / p_C.z() + cy);
  if (!InImage(uv)) return false;
  *uv_px = uv;
  return true;
}

Eigen::Vector2d CameraModel::Normalize(const Eigen::Vector2d& uv_px) const {
  return Eigen::Vector2d((uv_px.x() - cx) / fx, (uv_px.y() - cy) / fy);
}

bool CameraModel::HasDistortion() const {
  for (double k : distortion)
    if (k != 0.0) return true;
  return false;
}

Eigen::Vector2d CameraModel::Distort(const Eigen::Vector2d& xy) const {
  if (!HasDistortion()) return xy;
  const double k1 = distortion[0], k2 = distortion[1], p1 = distortion[2], p2 = distortion[3];
  const double x = xy.x(), y = xy.y(), r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (k1 + k2 * r2);
  return Eigen::Vector2d(x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
                         y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y);
}

Eigen::Vector2d CameraModel::Undistort(const Eigen::Vector2d& xy_distorted) const {
  if (!HasDistortion()) return xy_distorted;
  // x = (x_d - tangential(x)) / radial(x), iterated from x = x_d.
  const double k1 = distortion[0], k2 = distortion[1], p1 = distortion[2], p2 = distortion[3];
  Eigen::Vector2d xy = xy_distorted;
  for (int i = 0; i < 100; ++i) {
    const double x = xy.x(), y = xy.y(), r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (k1 + k2 * r2);
    const Eigen::Vector2d tangential(2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
                                     p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y);
    const Eigen::Vector2d next = (xy_distorted - tangential) / radial;
    const double step = (next - xy).norm();
    xy = next;
    if (step < 1e-12) break;
  }
  return xy;
}

Eigen::Vector2d CameraModel::DistortPixel(const Eigen::Vector2d& uv_px) const {
  const Eigen::Vector2d xy = Distort(Normalize(uv_px));
  return Eigen::Vector2d(fx * xy.x() + cx, fy * xy.y() + cy);
}

Eigen::Vector2d CameraModel::UndistortPixel(const Eigen::Vector2d& uv_image_px) const {
  const Eigen::Vector2d xy = Undistort(Normalize(uv_image_px));
  return Eigen::Vector2d(fx * xy.x() + cx, fy * xy.y() + cy);
}

}  // namespace vigil
