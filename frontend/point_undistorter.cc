#include "frontend/point_undistorter.h"

#include <stdexcept>

#include <opencv2/calib3d.hpp>

namespace vigil::frontend {

PointUndistorter::PointUndistorter(const CameraModel& camera) : distorted_(camera.HasDistortion()) {
  if (camera.distortion.size() != 4)
    throw std::invalid_argument("camera distortion: expected 4 numbers (k1, k2, p1, p2)");
  K_ = (cv::Mat_<double>(3, 3) << camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0);
  D_ = (cv::Mat_<double>(1, 4) << camera.distortion[0], camera.distortion[1], camera.distortion[2],
        camera.distortion[3]);
}

std::vector<cv::Point2f> PointUndistorter::Undistort(const std::vector<cv::Point2f>& raw_px) const {
  if (!distorted_ || raw_px.empty()) return raw_px;
  std::vector<cv::Point2f> out;
  // OpenCV's default is 5 fixed-point iterations, too few near the corners of a strongly distorted lens
  // (EuRoC's k1 = -0.28); iterate to convergence instead.
  cv::undistortPoints(raw_px, out, K_, D_, cv::noArray(), K_,
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-10));
  return out;
}

}  // namespace vigil::frontend
