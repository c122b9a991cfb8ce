#include "frontend/point_undistorter.h"

#include <vector>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>

namespace vigil::frontend {
namespace {

// EuRoC's cam0 (MH_01 ... V2_03): strong barrel distortion.
TrackerCamera EurocCam0() {
  TrackerCamera camera;
  camera.width = 752;
  camera.height = 480;
  camera.fx = 458.654;
  camera.fy = 457.296;
  camera.cx = 367.215;
  camera.cy = 248.375;
  camera.distortion = {-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05};
  return camera;
}

TEST(PointUndistorter, DistortMatchesOpenCvProjection) {
  const TrackerCamera camera = EurocCam0();
  const PointUndistorter undistorter(camera);
  const cv::Matx33d K(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  const std::vector<double> D(camera.distortion.begin(), camera.distortion.end());
  for (double x = -0.7; x <= 0.7; x += 0.1) {
    for (double y = -0.5; y <= 0.5; y += 0.1) {
      std::vector<cv::Point3d> ray = {{x, y, 1.0}};
      std::vector<cv::Point2d> projected;
      cv::projectPoints(ray, cv::Vec3d::zeros(), cv::Vec3d::zeros(), K, D, projected);
      const cv::Point2d d = undistorter.Distort({camera.fx * x + camera.cx, camera.fy * y + camera.cy});
      EXPECT_NEAR(d.x, projected[0].x, 1e-9);
      EXPECT_NEAR(d.y, projected[0].y, 1e-9);
    }
  }
}

TEST(PointUndistorter, UndistortInvertsTheModelOverTheWholeImage) {
  const TrackerCamera camera = EurocCam0();
  const PointUndistorter undistorter(camera);
  // Undistorted pixels whose raw pixel lies in the image, corners included.
  std::vector<cv::Point2d> truth;
  std::vector<cv::Point2f> raw;
  for (double u = -60; u <= camera.width + 60; u += 16) {
    for (double v = -40; v <= camera.height + 40; v += 16) {
      const cv::Point2d d = undistorter.Distort({u, v});
      if (d.x < 0 || d.y < 0 || d.x >= camera.width || d.y >= camera.height) continue;
      truth.push_back({u, v});
      raw.push_back(cv::Point2f(static_cast<float>(d.x), static_cast<float>(d.y)));
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

TEST(PointUndistorter, IdentityWithoutDistortion) {
  TrackerCamera camera;
  const PointUndistorter undistorter(camera);
  const std::vector<cv::Point2f> raw = {{1.25f, 2.5f}, {600.0f, 470.75f}};
  EXPECT_EQ(undistorter.Undistort(raw), raw);
}

}  // namespace
}  // namespace vigil::frontend
