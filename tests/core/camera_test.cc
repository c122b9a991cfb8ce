#include "core/camera.h"

#include <gtest/gtest.h>

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
  EXPECT_FALSE(cam.Project(Eigen::Vector3d(0, 0, -1), &uv));     // behind
  EXPECT_FALSE(cam.Project(Eigen::Vector3d(10, 0, 1), &uv));     // outside the image
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
