// The tracker's camera: a pinhole with radial-tangential distortion, and the undistortion of pixels.
//
// The raw image follows the OpenCV / EuRoC radial-tangential model: a normalized point (x, y) on the ideal
// pinhole plane appears at
//   r2 = x^2 + y^2,  x_d = x (1 + k1 r2 + k2 r2^2) + 2 p1 x y + p2 (r2 + 2 x^2),
//                    y_d = y (1 + k1 r2 + k2 r2^2) + p1 (r2 + 2 y^2) + 2 p2 x y,
//   (u, v) = (fx x_d + cx, fy y_d + cy).
// Undistortion inverts that: a raw pixel goes to the pixel of the same ray on the undistorted pinhole image
// with the same fx, fy, cx, cy (the estimator's pinhole CameraModel). Without distortion it is the identity.
#pragma once

#include <array>
#include <vector>

#include <opencv2/core.hpp>

namespace vigil::frontend {

struct TrackerCamera {
  int width = 640;
  int height = 480;
  double fx = 460.0, fy = 460.0, cx = 320.0, cy = 240.0;
  std::array<double, 4> distortion = {0.0, 0.0, 0.0, 0.0};  // k1, k2, p1, p2

  bool distorted() const {
    return distortion[0] != 0.0 || distortion[1] != 0.0 || distortion[2] != 0.0 || distortion[3] != 0.0;
  }
};

class PointUndistorter {
 public:
  explicit PointUndistorter(const TrackerCamera& camera);

  // Raw pixels -> undistorted pixels (iterative inversion to 1e-6 px, at most 50 iterations per point).
  std::vector<cv::Point2f> Undistort(const std::vector<cv::Point2f>& raw_px) const;
  // Undistorted pixel -> raw pixel (the forward model above).
  cv::Point2d Distort(const cv::Point2d& undistorted_px) const;

 private:
  TrackerCamera camera_;
  cv::Mat K_;  // 3x3 CV_64F
  cv::Mat D_;  // 1x4 CV_64F
};

}  // namespace vigil::frontend
