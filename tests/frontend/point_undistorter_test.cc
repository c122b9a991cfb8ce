#include "frontend/point_undistorter.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>

#include "tests/core/euroc_cam0.h"

namespace vigil::frontend {
namespace {

using vigil::testing::EurocCam0;

// The front-end inverts the camera model with OpenCV: core's DistortPixel must be OpenCV's projection.
TEST(PointUndistorter, CameraModelIsOpenCvsProjection) {
  const CameraModel camera = EurocCam0();
  const cv::Matx33d K(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  const std::vector<double> D(camera.distortion.begin(), camera.distortion.end());
  for (double x = -0.7; x <= 0.7; x += 0.1) {
    for (double y = -0.5; y <= 0.5; y += 0.1) {
      std::vector<cv::Point3d> ray = {{x, y, 1.0}};
      std::vector<cv::Point2d> projected;
      cv::projectPoints(ray, cv::Vec3d::zeros(), cv::Vec3d::zeros(), K, D, projected);
      const Eigen::Vector2d d = camera.DistortPixel({camera.fx * x + camera.cx, camera.fy * y + camera.cy});
      EXPECT_NEAR(d.x(), projected[0].x, 1e-9);
      EXPECT_NEAR(d.y(), projected[0].y, 1e-9);
    }
  }
}

TEST(PointUndistorter, UndistortInvertsTheModelOverTheWholeImage) {
  const CameraModel camera = EurocCam0();
  const PointUndistorter undistorter(camera);
  // Undistorted pixels whose raw pixel lies in the image, corners included.
  std::vector<cv::Point2d> truth;
  std::vector<cv::Point2f> raw;
  for (double u = -60; u <= camera.width + 60; u += 16) {
    for (double v = -40; v <= camera.height + 40; v += 16) {
      const Eigen::Vector2d d = camera.DistortPixel({u, v});
      if (!camera.InImage(d)) continue;
      truth.push_back({u, v});
      raw.push_back(cv::Point2f(static_cast<float>(d.x()), static_cast<float>(d.y())));
    }
  }
  ASSERT_GT(raw.size(), 1000u);
  const std::vector<cv::Point2f> out = undistorter.Undistort(raw);
  ASSERT_EQ(out.size(), raw.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < out.size(); ++i)
    worst = std::max(worst, cv::norm(cv::Point2d(out[i].x, out[i].y) - truth[i]));
  // float pixels (what the tracker holds) carry about 3e-5 px of rounding at these magnitudes
  EXPECT_LT(worst, 2e-3);

  // OpenCV's default (5 iterations) is visibly worse near the corners: the reason for iterating further.
  const cv::Matx33d K(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  const std::vector<double> D(camera.distortion.begin(), camera.distortion.end());
  std::vector<cv::Point2f> coarse;
  cv::undistortPoints(raw, coarse, K, D, cv::noArray(), K);
  double coarse_worst = 0.0;
  for (std::size_t i = 0; i < coarse.size(); ++i)
    coarse_worst = std::max(coarse_worst, cv::norm(cv::Point2d(coarse[i].x, coarse[i].y) - truth[i]));
  EXPECT_GT(coarse_worst, 10 * worst);
}

// OpenCV's inversion (float pixels) and the camera model's own (double) agree to a float's resolution.
TEST(PointUndistorter, AgreesWithTheCameraModelsUndistortion) {
  const CameraModel camera = EurocCam0();
  const PointUndistorter undistorter(camera);
  std::vector<cv::Point2f> raw;
  for (float v = 0.0f; v < static_cast<float>(camera.height); v += 7.3f)
    for (float u = 0.0f; u < static_cast<float>(camera.width); u += 5.9f) raw.push_back({u, v});
  const std::vector<cv::Point2f> out = undistorter.Undistort(raw);
  ASSERT_EQ(out.size(), raw.size());
  double worst_px = 0.0;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const Eigen::Vector2d model = camera.UndistortPixel({raw[i].x, raw[i].y});
    worst_px = std::max(worst_px, (model - Eigen::Vector2d(out[i].x, out[i].y)).norm());
  }
  // one float ulp at up to 1,024 px is 6.1e-5 px
  EXPECT_LE(worst_px, 6.2e-5);
}

TEST(PointUndistorter, IdentityWithoutDistortion) {
  const CameraModel camera;
  const PointUndistorter undistorter(camera);
  const std::vector<cv::Point2f> raw = {{1.25f, 2.5f}, {600.0f, 470.75f}};
  EXPECT_EQ(undistorter.Undistort(raw), raw);
}

}  // namespace
}  // namespace vigil::frontend
