// The front-end's undistortion of tracked pixels for a core CameraModel (core/camera.h: pinhole with
// radial-tangential lens distortion, the model of EuRoC and OpenCV).
//
// A raw image pixel goes to the pixel of the same ray on the undistorted pinhole image with the same fx, fy,
// cx, cy: the inverse of CameraModel::DistortPixel. Without distortion it is the identity.
//
// The inversion is OpenCV's cv::undistortPoints on float pixels, iterated to convergence (its reprojection
// error below 1e-10 px, at most 50 iterations per point). CameraModel::UndistortPixel inverts the same model
// in double precision by its own fixed-point iteration (stopping on a step below 1e-12); both agree to well
// within a float's resolution, but about 1 point in 100,000 rounds to the neighbouring float, so the
// front-end keeps OpenCV's inversion that its tracks have always used.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"

namespace vigil::frontend {

class PointUndistorter {
 public:
  explicit PointUndistorter(const CameraModel& camera);

  // Raw pixels -> undistorted pixels.
  std::vector<cv::Point2f> Undistort(const std::vector<cv::Point2f>& raw_px) const;

 private:
  bool distorted_ = false;
  cv::Mat K_;  // 3x3 CV_64F
  cv::Mat D_;  // 1x4 CV_64F
};

}  // namespace vigil::frontend
