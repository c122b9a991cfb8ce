#include "core/camera.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "tests/core/euroc_cam0.h"

namespace vigil {
namespace {

TEST(Camera, DefaultExtrinsicsLookAlongMinusXOfTheBody) {
  const CameraModel cam;
  EXPECT_EQ(cam.Validate(), "");
  const Eigen::Matrix3d R = cam.R_BC();
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
  EXPECT_LT((R * Eigen::Vector3d::UnitZ() - Eigen::Vector3d(-1, 0, 0)).norm(), 1e-12);  // cam z = -x_B
  EXPECT_LT((R * Eigen::Vector3d::UnitX() - Eigen::Vector3d(0, -1, 0)).norm(), 1e-12);  // cam x = -y_B
  EXPECT_LT((R * Eigen::Vector3d::UnitY() - Eigen::Vector3d(0, 0, 1)).norm(), 1e-12);   // cam y = +z_B
  EXPECT_EQ(cam.p_BC(), Eigen::Vector3d(0.05, 0.04, 0.03));
}

TEST(Camera, ProjectsAndNormalizesConsistently) {
  const CameraModel cam;
  Eigen::Vector2d uv;
  ASSERT_TRUE(cam.Project(Eigen::Vector3d(0.5, -0.25, 2.0), &uv));
  EXPECT_NEAR(uv.x(), 460 * 0.25 + 255, 1e-12);
  EXPECT_NEAR(uv.y(), 460 * -0.125 + 255, 1e-12);
  EXPECT_LT((cam.Normalize(uv) - Eigen::Vector2d(0.25, -0.125)).norm(), 1e-12);
  EXPECT_FALSE(cam.Project(Eigen::Vector3d(0, 0, -1), &uv));  // behind
  EXPECT_FALSE(cam.Project(Eigen::Vector3d(10, 0, 1), &uv));  // outside the image
}

TEST(Camera, RejectsImproperRotation) {
  CameraModel cam;
  cam.T_BC = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};
  EXPECT_NE(cam.Validate().find("proper rotation"), std::string::npos);
  cam.T_BC.resize(15);
  EXPECT_NE(cam.Validate().find("16 numbers"), std::string::npos);
}

}  // namespace
}  // namespace vigil

namespace vigil {
namespace {

using vigil::testing::EurocCam0;

TEST(CameraDistortion, NoneByDefaultLeavesPixelsUnchanged) {
  const CameraModel cam;
  EXPECT_FALSE(cam.HasDistortion());
  const Eigen::Vector2d uv(12.5, 600.25);
  EXPECT_EQ(cam.DistortPixel(uv), uv);
  EXPECT_EQ(cam.UndistortPixel(uv), uv);
}

TEST(CameraDistortion, MatchesTheRadialTangentialFormula) {
  const CameraModel cam = EurocCam0();
  const double x = 0.3, y = -0.2, r2 = x * x + y * y;
  const double k1 = cam.distortion[0], k2 = cam.distortion[1], p1 = cam.distortion[2], p2 = cam.distortion[3];
  const Eigen::Vector2d d = cam.Distort(Eigen::Vector2d(x, y));
  EXPECT_NEAR(d.x(), x * (1 + k1 * r2 + k2 * r2 * r2) + 2 * p1 * x * y + p2 * (r2 + 2 * x * x), 1e-15);
  EXPECT_NEAR(d.y(), y * (1 + k1 * r2 + k2 * r2 * r2) + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y, 1e-15);
  // Barrel distortion (k1 < 0) pulls points towards the centre.
  EXPECT_LT(d.norm(), Eigen::Vector2d(x, y).norm());
}

TEST(CameraDistortion, UndistortInvertsDistortOverTheEurocImage) {
  const CameraModel cam = EurocCam0();
  double worst_px = 0.0;
  for (int v = 0; v <= cam.height; v += 40) {
    for (int u = 0; u <= cam.width; u += 47) {
      const Eigen::Vector2d image(u, v);
      const Eigen::Vector2d pinhole = cam.UndistortPixel(image);
      worst_px = std::max(worst_px, (cam.DistortPixel(pinhole) - image).norm());
      // Away from the centre the pinhole pixel lies further out than the image pixel (barrel).
      if ((image - Eigen::Vector2d(cam.cx, cam.cy)).norm() > 100) {
        EXPECT_GT((pinhole - Eigen::Vector2d(cam.cx, cam.cy)).norm(),
                  (image - Eigen::Vector2d(cam.cx, cam.cy)).norm());
      }
    }
  }
  EXPECT_LT(worst_px, 1e-6);
}

TEST(CameraDistortion, ValidateNeedsFourFiniteCoefficients) {
  CameraModel cam;
  cam.distortion = {0.1, 0.2};
  EXPECT_NE(cam.Validate().find("distortion"), std::string::npos);
  cam.distortion = {0.1, 0.2, 0.0, std::nan("")};
  EXPECT_NE(cam.Validate().find("finite"), std::string::npos);
}

}  // namespace
}  // namespace vigil
