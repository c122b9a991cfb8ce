// Analytic Jacobians of the factors against central differences through the pose manifold.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "core/random.h"
#include "core/so3.h"
#include "estimator/bias_prior_factor.h"
#include "estimator/imu_factor.h"
#include "estimator/marginalization.h"
#include "estimator/point_reprojection_factor.h"
#include "estimator/pose_manifold.h"
#include "estimator/reprojection_factor.h"
#include "estimator/zero_velocity_factor.h"

namespace vigil::estimator {
namespace {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// x [+] delta for a block (pose: manifold, else vector addition).
std::vector<double> PlusBlock(const std::vector<double>& x, const Eigen::VectorXd& delta) {
  std::vector<double> out(x.size());
  if (x.size() == kPoseSize) {
    PoseManifold().Plus(x.data(), delta.data(), out.data());
  } else {
    for (std::size_t i = 0; i < x.size(); ++i) out[i] = x[i] + delta[static_cast<int>(i)];
  }
  return out;
}

// Checks every block's tangent Jacobian against central differences; returns the worst relative error.
double WorstJacobianError(const ceres::CostFunction& cost, std::vector<std::vector<double>> blocks) {
  const int rows = cost.num_residuals();
  const std::vector<int32_t>& sizes = cost.parameter_block_sizes();
  std::vector<const double*> ptrs;
  for (auto& b : blocks) ptrs.push_back(b.data());
  std::vector<RowMajorMatrix> jac(blocks.size());
  std::vector<double*> jac_ptrs;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    jac[k].resize(rows, sizes[k]);
    jac_ptrs.push_back(jac[k].data());
  }
  Eigen::VectorXd r0(rows);
  EXPECT_TRUE(cost.Evaluate(ptrs.data(), r0.data(), jac_ptrs.data()));
  double worst = 0.0;
  const double h = 1e-6;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const int tangent = TangentSizeOf(sizes[k]);
    if (sizes[k] == kPoseSize) {
      EXPECT_LT(jac[k].col(6).norm(), 1e-15);  // the tangent convention
    }
    for (int c = 0; c < tangent; ++c) {
      Eigen::VectorXd delta = Eigen::VectorXd::Zero(tangent);
      std::vector<std::vector<double>> plus = blocks, minus = blocks;
      delta[c] = h;
      plus[k] = PlusBlock(blocks[k], delta);
      minus[k] = PlusBlock(blocks[k], -delta);
      Eigen::VectorXd rp(rows), rm(rows);
      std::vector<const double*> pp, pm;
      for (std::size_t i = 0; i < blocks.size(); ++i) {
        pp.push_back(plus[i].data());
        pm.push_back(minus[i].data());
      }
      EXPECT_TRUE(cost.Evaluate(pp.data(), rp.data(), nullptr));
      EXPECT_TRUE(cost.Evaluate(pm.data(), rm.data(), nullptr));
      const Eigen::VectorXd numeric = (rp - rm) / (2.0 * h);
      const double err = (numeric - jac[k].col(c)).norm() / (1.0 + numeric.norm());
      EXPECT_LT(err, 1e-5) << "block " << k << " column " << c << "\nnumeric  " << numeric.transpose()
                           << "\nanalytic " << jac[k].col(c).transpose();
      worst = std::max(worst, err);
    }
  }
  return worst;
}

std::vector<double> Pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  return {p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()};
}

Eigen::Vector3d RandomVector(Rng& rng, double scale) { return Eigen::Vector3d(scale * rng.NormalVector3()); }

TEST(FactorJacobianTest, ImuFactor) {
  Rng rng(11, "imu_factor_test");
  Preintegration pre(Eigen::Vector3d(0.2, -0.1, 9.7), Eigen::Vector3d(0.3, 0.1, -0.2),
                     Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d(0, 0.01, 0), ImuNoiseDensities{}, 200.0);
  Eigen::Vector3d a(0.2, -0.1, 9.7), w(0.3, 0.1, -0.2);
  for (int k = 0; k < 20; ++k) {
    a += RandomVector(rng, 0.3);
    w += RandomVector(rng, 0.05);
    pre.Push(0.005, a, w);
  }
  const ImuFactor factor(pre, Eigen::Vector3d(0, 0, -9.81));
  // A state pair that does not satisfy the factor, with biases away from the linearization point.
  const std::vector<double> pose_i = Pose(Eigen::Vector3d(1, 2, 3), ExpQ(Eigen::Vector3d(0.1, -0.2, 0.3)));
  const std::vector<double> pose_j =
      Pose(Eigen::Vector3d(1.2, 2.1, 2.9), ExpQ(Eigen::Vector3d(0.15, -0.1, 0.4)));
  const std::vector<double> sb_i = {0.5, 0.2, -0.1, 0.07, -0.02, 0.03, 0.004, 0.012, -0.003};
  const std::vector<double> sb_j = {0.6, 0.1, -0.2, 0.06, -0.01, 0.02, 0.005, 0.011, -0.002};
  WorstJacobianError(factor, {pose_i, sb_i, pose_j, sb_j});
}

// In-estimator mitigation: a preintegration with inflated samples (detector flags, clipping) and a gated
// factor (inflated covariance) keep analytic Jacobians that match central differences, and the gate scales
// the whitened residual by 1 / sqrt(inflation).
TEST(FactorJacobianTest, ImuFactorWithInflatedSamplesAndGating) {
  Rng rng(12, "imu_factor_test");
  Preintegration pre(Eigen::Vector3d(0.2, -0.1, 9.7), Eigen::Vector3d(0.3, 0.1, -0.2),
                     Eigen::Vector3d(0.05, 0, 0), Eigen::Vector3d(0, 0.01, 0), ImuNoiseDensities{}, 200.0,
                     1e4);
  Eigen::Vector3d a(0.2, -0.1, 9.7), w(0.3, 0.1, -0.2);
  for (int k = 0; k < 20; ++k) {
    a += RandomVector(rng, 0.3);
    w += RandomVector(rng, 0.05);
    pre.Push(0.005, a + (k == 7 ? Eigen::Vector3d(0, 0, 50) : Eigen::Vector3d::Zero()), w,
             k == 7 || k == 8 ? 1e4 : 1.0);
  }
  ImuFactor factor(pre, Eigen::Vector3d(0, 0, -9.81));
  const std::vector<double> pose_i = Pose(Eigen::Vector3d(1, 2, 3), ExpQ(Eigen::Vector3d(0.1, -0.2, 0.3)));
  const std::vector<double> pose_j =
      Pose(Eigen::Vector3d(1.2, 2.1, 2.9), ExpQ(Eigen::Vector3d(0.15, -0.1, 0.4)));
  const std::vector<double> sb_i = {0.5, 0.2, -0.1, 0.07, -0.02, 0.03, 0.004, 0.012, -0.003};
  const std::vector<double> sb_j = {0.6, 0.1, -0.2, 0.06, -0.01, 0.02, 0.005, 0.011, -0.002};
  WorstJacobianError(factor, {pose_i, sb_i, pose_j, sb_j});
  Eigen::Matrix<double, 15, 1> r_nominal, r_gated;
  const double* p[4] = {pose_i.data(), sb_i.data(), pose_j.data(), sb_j.data()};
  ASSERT_TRUE(factor.Evaluate(p, r_nominal.data(), nullptr));
  factor.InflateCovariance(9.0);
  EXPECT_DOUBLE_EQ(factor.covariance_inflation(), 9.0);
  WorstJacobianError(factor, {pose_i, sb_i, pose_j, sb_j});
  ASSERT_TRUE(factor.Evaluate(p, r_gated.data(), nullptr));
  EXPECT_LT((r_gated - r_nominal / 3.0).norm(), 1e-12 * r_nominal.norm());
}

TEST(FactorJacobianTest, ZeroVelocityFactors) {
  const ZeroVelocityFactor velocity(0.01);
  const std::vector<double> sb = {0.5, 0.2, -0.1, 0.07, -0.02, 0.03, 0.004, 0.012, -0.003};
  WorstJacobianError(velocity, {sb});
  Eigen::Vector3d r;
  const double* v[1] = {sb.data()};
  ASSERT_TRUE(velocity.Evaluate(v, r.data(), nullptr));
  EXPECT_LT((r - Eigen::Vector3d(50, 20, -10)).norm(), 1e-12);  // the velocity over its std, biases unused
  // Two poses that differ (the residual is not at its zero), and two that are equal (it is).
  const NoMotionFactor motion(0.002, 0.01);
  const std::vector<double> pose_i = Pose(Eigen::Vector3d(1, 2, 3), ExpQ(Eigen::Vector3d(0.1, -0.2, 0.3)));
  const std::vector<double> pose_j =
      Pose(Eigen::Vector3d(1.02, 1.99, 3.01), ExpQ(Eigen::Vector3d(0.12, -0.25, 0.28)));
  WorstJacobianError(motion, {pose_i, pose_j});
  WorstJacobianError(motion, {pose_i, pose_i});
  Eigen::Matrix<double, 6, 1> r6;
  const double* same[2] = {pose_i.data(), pose_i.data()};
  ASSERT_TRUE(motion.Evaluate(same, r6.data(), nullptr));
  EXPECT_LT(r6.norm(), 1e-12);
  const double* differ[2] = {pose_i.data(), pose_j.data()};
  ASSERT_TRUE(motion.Evaluate(differ, r6.data(), nullptr));
  EXPECT_LT((r6.head<3>() - Eigen::Vector3d(10, -5, 5)).norm(), 1e-9);
}

TEST(FactorJacobianTest, BiasPriorFactor) {
  const BiasPriorFactor factor(Eigen::Vector3d(0.02, -0.05, 0.1), Eigen::Vector3d(0.001, 0.002, -0.003), 0.1,
                               0.01);
  const std::vector<double> sb = {0.5, 0.2, -0.1, 0.07, -0.02, 0.03, 0.004, 0.012, -0.003};
  WorstJacobianError(factor, {sb});
  // The residual: the bias offsets over their std, the velocity untouched.
  Eigen::Matrix<double, 6, 1> r;
  const double* p[1] = {sb.data()};
  ASSERT_TRUE(factor.Evaluate(p, r.data(), nullptr));
  EXPECT_NEAR(r[0], (0.07 - 0.02) / 0.1, 1e-12);
  EXPECT_NEAR(r[2], (0.03 - 0.1) / 0.1, 1e-12);
  EXPECT_NEAR(r[4], (0.012 - 0.002) / 0.01, 1e-12);
  // A std of 0 switches that half off.
  const BiasPriorFactor gyro_only(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0, 0.01);
  ASSERT_TRUE(gyro_only.Evaluate(p, r.data(), nullptr));
  EXPECT_EQ(r.head<3>().norm(), 0.0);
  EXPECT_GT(r.tail<3>().norm(), 0.0);
}

TEST(FactorJacobianTest, ReprojectionFactor) {
  Eigen::Isometry3d T_BC = Eigen::Isometry3d::Identity();
  T_BC.linear() << 0, 0, -1, -1, 0, 0, 0, 1, 0;
  T_BC.translation() = Eigen::Vector3d(0.05, 0.04, 0.03);
  const ReprojectionFactor factor(Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(0.12, -0.18), T_BC,
                                  460.0 / 1.5);
  const std::vector<double> pose_i = Pose(Eigen::Vector3d(0, 0, 0), ExpQ(Eigen::Vector3d(0.01, 0.02, 0.1)));
  const std::vector<double> pose_j =
      Pose(Eigen::Vector3d(0.1, 0.3, -0.05), ExpQ(Eigen::Vector3d(0.0, 0.05, 0.2)));
  WorstJacobianError(factor, {pose_i, pose_j, {0.2}});
}

// A landmark point's factor: its Jacobians, and the same residual as the anchored-depth factor for the same
// point in W.
TEST(FactorJacobianTest, PointReprojectionFactor) {
  Eigen::Isometry3d T_BC = Eigen::Isometry3d::Identity();
  T_BC.linear() << 0, 0, -1, -1, 0, 0, 0, 1, 0;
  T_BC.translation() = Eigen::Vector3d(0.05, 0.04, 0.03);
  const Eigen::Vector2d n_i(0.1, -0.2), n_j(0.12, -0.18);
  const double rho = 0.2;
  const std::vector<double> pose_i = Pose(Eigen::Vector3d(0, 0, 0), ExpQ(Eigen::Vector3d(0.01, 0.02, 0.1)));
  const std::vector<double> pose_j =
      Pose(Eigen::Vector3d(0.1, 0.3, -0.05), ExpQ(Eigen::Vector3d(0.0, 0.05, 0.2)));
  const Eigen::Isometry3d T_WB_i = Eigen::Translation3d(PoseP(pose_i.data())) * PoseQ(pose_i.data());
  const Eigen::Vector3d p_W = T_WB_i * T_BC * (Eigen::Vector3d(n_i.x(), n_i.y(), 1.0) / rho);
  const std::vector<double> point = {p_W.x(), p_W.y(), p_W.z()};
  const PointReprojectionFactor factor(n_j, T_BC, 460.0 / 1.5);
  WorstJacobianError(factor, {pose_j, point});

  const ReprojectionFactor anchored(n_i, n_j, T_BC, 460.0 / 1.5);
  Eigen::Vector2d r_point, r_anchored;
  const double* point_blocks[2] = {pose_j.data(), point.data()};
  const double depth = rho;
  const double* anchored_blocks[3] = {pose_i.data(), pose_j.data(), &depth};
  ASSERT_TRUE(factor.Evaluate(point_blocks, r_point.data(), nullptr));
  ASSERT_TRUE(anchored.Evaluate(anchored_blocks, r_anchored.data(), nullptr));
  EXPECT_GT(r_point.norm(), 1.0);
  EXPECT_LT((r_point - r_anchored).norm(), 1e-9);
}

// A prior built from a reprojection and an IMU factor: its Jacobian and its residual around x0.
TEST(FactorJacobianTest, MarginalizationFactor) {
  Eigen::Isometry3d T_BC = Eigen::Isometry3d::Identity();
  std::vector<double> pose_i = Pose(Eigen::Vector3d(0, 0, 0), ExpQ(Eigen::Vector3d(0.01, 0.02, 0.1)));
  std::vector<double> pose_j = Pose(Eigen::Vector3d(0.1, 0.3, -0.05), ExpQ(Eigen::Vector3d(0.0, 0.05, 0.2)));
  std::vector<double> pose_k = Pose(Eigen::Vector3d(0.3, 0.2, 0.05), ExpQ(Eigen::Vector3d(0.05, 0.0, 0.3)));
  std::vector<double> depth = {0.25};
  const ReprojectionFactor f1(Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(0.12, -0.18), T_BC, 300.0);
  const ReprojectionFactor f2(Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(0.15, -0.1), T_BC, 300.0);
  const std::vector<MarginalizationTerm> terms = {
      {&f1, nullptr, {pose_i.data(), pose_j.data(), depth.data()}},
      {&f2, nullptr, {pose_i.data(), pose_k.data(), depth.data()}}};
  auto prior = std::make_shared<LinearPrior>();
  ASSERT_TRUE(Marginalize(nullptr, terms, {pose_i.data(), depth.data()}, 1e-8, prior.get()));
  ASSERT_EQ(prior->blocks.size(), 2u);
  const MarginalizationFactor factor(prior);
  std::vector<double> pose_j_moved =
      PlusBlock(pose_j, (Eigen::VectorXd(6) << 0.1, -0.05, 0.02, 0.1, 0.2, -0.1).finished());
  WorstJacobianError(factor, {pose_j_moved, pose_k});

  // At x0 the prior's gradient J^T r equals the Schur complement's b: compare with the direct computation
  // from the full normal equations.
  Eigen::MatrixXd J(4, 13);
  Eigen::VectorXd r(4);
  {
    RowMajorMatrix ji(2, 7), jj(2, 7), jd(2, 1);
    double* jac[3] = {ji.data(), jj.data(), jd.data()};
    const double* p1[3] = {pose_i.data(), pose_j.data(), depth.data()};
    ASSERT_TRUE(f1.Evaluate(p1, r.data(), jac));
    J.setZero();
    J.block(0, 0, 2, 6) = ji.leftCols(6);
    J.block(0, 6, 2, 1) = jd;
    J.block(0, 7, 2, 6) = jj.leftCols(6);
  }
  Eigen::MatrixXd J2(2, 19);
  {
    RowMajorMatrix ji(2, 7), jk(2, 7), jd(2, 1);
    double* jac[3] = {ji.data(), jk.data(), jd.data()};
    const double* p2[3] = {pose_i.data(), pose_k.data(), depth.data()};
    Eigen::Vector2d r2;
    ASSERT_TRUE(f2.Evaluate(p2, r2.data(), jac));
    J2.setZero();
    J2.block(0, 0, 2, 6) = ji.leftCols(6);
    J2.block(0, 6, 2, 1) = jd;
    J2.block(0, 13, 2, 6) = jk.leftCols(6);
    r.tail<2>() = r2;
  }
  Eigen::MatrixXd Jfull(4, 19);
  Jfull.setZero();
  Jfull.topLeftCorner(2, 13) = J.topRows(2);
  Jfull.bottomRows(2) = J2;
  const Eigen::MatrixXd H = Jfull.transpose() * Jfull;
  const Eigen::VectorXd b = Jfull.transpose() * r;
  const Eigen::MatrixXd Hmm = H.topLeftCorner(7, 7);
  const Eigen::MatrixXd pinv = Hmm.completeOrthogonalDecomposition().pseudoInverse();
  const Eigen::MatrixXd S =
      H.bottomRightCorner(12, 12) - H.bottomLeftCorner(12, 7) * pinv * H.topRightCorner(7, 12);
  const Eigen::VectorXd bs = b.tail(12) - H.bottomLeftCorner(12, 7) * pinv * b.head(7);
  EXPECT_LT((prior->J.transpose() * prior->J - S).norm(), 1e-6 * S.norm());
  EXPECT_LT((prior->J.transpose() * prior->r - bs).norm(), 1e-6 * (1.0 + bs.norm()));
}

}  // namespace
}  // namespace vigil::estimator
