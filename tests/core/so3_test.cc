#include "core/so3.h"

#include <cmath>

#include <gtest/gtest.h>

namespace vigil {
namespace {

TEST(So3, ExpAndLogAreInverse) {
  for (const Eigen::Vector3d& phi : {Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(1e-10, 0, 2e-10),
                                     Eigen::Vector3d(0, 3.0, 0), Eigen::Vector3d(-1.2, 0.4, 2.0)}) {
    EXPECT_LT((LogQ(ExpQ(phi)) - phi).norm(), 1e-12) << phi.transpose();
    const Eigen::AngleAxisd aa(phi.norm(),
                               phi.norm() > 0 ? Eigen::Vector3d(phi.normalized()) : Eigen::Vector3d::UnitX());
    EXPECT_LT(ExpQ(phi).angularDistance(Eigen::Quaterniond(aa)), 1e-12);
  }
}

TEST(So3, RightJacobianMatchesFiniteDifferences) {
  // Exp(phi + d) ~= Exp(phi) Exp(Jr(phi) d)
  const Eigen::Vector3d phi(0.3, -0.5, 0.8);
  const double h = 1e-6;
  Eigen::Matrix3d numeric;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d d = h * Eigen::Vector3d::Unit(i);
    numeric.col(i) = LogQ(ExpQ(phi).conjugate() * ExpQ(phi + d)) / h;
  }
  EXPECT_LT((numeric - RightJacobian(phi)).norm(), 1e-5);
  EXPECT_LT((RightJacobian(phi) * RightJacobianInverse(phi) - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

TEST(So3, SkewIsTheCrossProduct) {
  const Eigen::Vector3d a(1, 2, 3), b(-4, 0.5, 2);
  EXPECT_LT((Skew(a) * b - a.cross(b)).norm(), 1e-15);
}

TEST(So3, YawOfRotZ) {
  EXPECT_NEAR(YawOf(RotZ(2.5)), 2.5, 1e-12);
  EXPECT_NEAR(YawOf(RotZ(-0.7) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY()).toRotationMatrix()), -0.7,
              1e-12);
}

}  // namespace
}  // namespace vigil
