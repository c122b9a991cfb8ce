#include "frontend/point_undistorter.h"

#include <opencv2/calib3d.hpp>

namespace vigil::frontend {

PointUndistorter::PointUndistorter(const TrackerCamera& camera) : camera_(camera) {
  K_ = (cv::Mat_<double>(3, 3) << camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0);
  D_ = (cv::Mat_<double>(1, 4) << camera.distortion[0], camera.distortion[1], camera.distortion[2],
        camera.distortion[3]);
}

std::vector<cv::Point2f> PointUndistorter::Undistort(const std::vector<cv::Point2f>& raw_px) const {
  if (!camera_.distorted() || raw_px.empty()) return raw_px;
  std::vector<cv::Point2f> out;
  // OpenCV's default is 5 fixed-point iterations, too few near the corners of a strongly distorted lens
  // (EuRoC's k1 = -0.28); iterate to convergence instead.
  cv::undistortPoints(raw_px, out, K_, D_, cv::noArray(), K_,
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-10));
  return out;
}

cv::Point2d PointUndistorter::Distort(const cv::Point2d& undistorted_px) const {
  const auto& [k1, k2, p1, p2] = camera_.distortion;
  const double x = (undistorted_px.x - camera_.cx) / camera_.fx;
  const double y = (undistorted_px.y - camera_.cy) / camera_.fy;
  const double r2 = x * x + y * y;
  const double radial = 1.0 + k1 * r2 + k2 * r2 * r2;
  const double xd = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x);
  const double yd = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y;
  return {camera_.fx * xd + camera_.cx, camera_.fy * yd + camera_.cy};
}

}  // namespace vigil::frontend
