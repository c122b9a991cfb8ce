#include "estimator/init/visual_inertial_alignment.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "core/so3.h"
#include "simulated_window.h"

namespace vigil::estimator {
namespace {

// Alignment inputs from ground truth: exact rotations in an arbitrary frame L, camera positions divided by
// `scale_truth`, IMU from an ideal simulated IMU with constant biases.
struct ExactInputs {
  Dataset data;
  std::vector<InitFrame> window;
  std::vector<AlignmentFrame> frames;
  Eigen::Matrix3d R_LW;
  Eigen::Vector3d p_BC;
};

ExactInputs MakeExactInputs(const Eigen::Vector3d& b_g, double scale_truth) {
  ExactInputs in;
  in.data = sim::Simulate(testing::WindowSimOptions(0.0, b_g, Eigen::Vector3d::Zero()), 3);
  in.window = testing::MakeWindow(in.data, 5, 11, ImuNoiseDensities{});
  in.R_LW = ExpQ(Eigen::Vector3d(0.3, -1.0, 2.0)).toRotationMatrix();
  in.p_BC = in.data.camera.p_BC();
  for (std::size_t k = 0; k < in.window.size(); ++k) {
    const NavState& x = testing::TruthAt(in.data, in.window[k].t_ns);
    AlignmentFrame f;
    f.R_LB = in.R_LW * x.q_WB.toRotationMatrix();
    const Eigen::Vector3d p_WC = x.p_W + x.q_WB * in.p_BC;
    f.p_LC = in.R_LW * (p_WC - Eigen::Vector3d(20, 5, 5)) / scale_truth;
    f.imu_from_prev = in.window[k].imu_from_prev ? &*in.window[k].imu_from_prev : nullptr;
    in.frames.push_back(f);
  }
  return in;
}

TEST(SolveGyroBias, RecoversAConstantBias) {
  const Eigen::Vector3d b_g_true(0.03, -0.02, 0.025);
  const ExactInputs in = MakeExactInputs(b_g_true, 1.0);
  Eigen::Vector3d b_g;
  ASSERT_TRUE(SolveGyroBias(in.frames, Eigen::Vector3d::Zero(), 3, &b_g));
  EXPECT_LT((b_g - b_g_true).norm(), 0.01 * b_g_true.norm()) << b_g.transpose();
}

// With the bias solved, exact rotations leave no residual; one pair whose vision rotation is off by 5 deg (a
// glitch burst the gyroscope saw, in the initializer) shows it there, and the bias spreads little of it over
// the other pairs.
TEST(GyroRotationResiduals, ShowWhatTheBiasCannotExplain) {
  const Eigen::Vector3d b_g_true(0.03, -0.02, 0.025);
  ExactInputs in = MakeExactInputs(b_g_true, 1.0);
  Eigen::Vector3d b_g;
  ASSERT_TRUE(SolveGyroBias(in.frames, Eigen::Vector3d::Zero(), 3, &b_g));
  const std::vector<double> clean = GyroRotationResiduals(in.frames, b_g);
  ASSERT_EQ(clean.size(), in.frames.size() - 1);
  for (double r : clean) EXPECT_LT(r * 180.0 / M_PI, 0.05);

  // Frames 4 on rotated 5 deg about the body's z: only the pair (3, 4) changes.
  const Eigen::Matrix3d kick =
      Eigen::AngleAxisd(5.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (std::size_t k = 4; k < in.frames.size(); ++k) in.frames[k].R_LB = in.frames[k].R_LB * kick;
  ASSERT_TRUE(SolveGyroBias(in.frames, Eigen::Vector3d::Zero(), 3, &b_g));
  const std::vector<double> kicked = GyroRotationResiduals(in.frames, b_g);
  const auto worst = std::max_element(kicked.begin(), kicked.end());
  EXPECT_EQ(worst - kicked.begin(), 3);
  EXPECT_GT(*worst * 180.0 / M_PI, 4.0);
  for (std::size_t k = 0; k < kicked.size(); ++k) {
    if (k == 3) continue;
    EXPECT_LT(kicked[k] * 180.0 / M_PI, 1.0) << "pair " << k;
  }

  in.frames[2].imu_from_prev = nullptr;
  EXPECT_TRUE(GyroRotationResiduals(in.frames, b_g).empty());
}

TEST(LinearAlignment, RecoversScaleGravityAndVelocities) {
  const double scale_truth = 3.7;
  ExactInputs in = MakeExactInputs(Eigen::Vector3d::Zero(), scale_truth);
  Alignment a;
  std::string why;
  ASSERT_TRUE(LinearAlignment(in.frames, in.p_BC, 9.81, 1.0, &a, &why)) << why;
  EXPECT_NEAR(a.scale, scale_truth, 0.005 * scale_truth);
  const Eigen::Vector3d g_L_true = in.R_LW * Eigen::Vector3d(0, 0, -9.81);
  EXPECT_LT((a.g_L - g_L_true).norm(), 0.05);
  for (std::size_t k = 0; k < in.window.size(); ++k) {
    const Eigen::Vector3d v_L_true = in.R_LW * testing::TruthAt(in.data, in.window[k].t_ns).v_W;
    EXPECT_LT((a.v_L[k] - v_L_true).norm(), 0.02) << "frame " << k;
  }
  // Gravity refinement keeps the answer, with |g| exact.
  ASSERT_TRUE(RefineGravity(in.frames, in.p_BC, 9.81, 4, &a, &why)) << why;
  EXPECT_NEAR(a.g_L.norm(), 9.81, 1e-9);
  EXPECT_LT(std::acos(a.g_L.normalized().dot(g_L_true.normalized())), 0.05 * M_PI / 180);
  EXPECT_NEAR(a.scale, scale_truth, 0.005 * scale_truth);
}

TEST(RefineGravity, PullsAWrongDirectionBackOntoTheTruth) {
  ExactInputs in = MakeExactInputs(Eigen::Vector3d::Zero(), 1.0);
  const Eigen::Vector3d g_L_true = in.R_LW * Eigen::Vector3d(0, 0, -9.81);
  Alignment a;
  a.g_L = ExpQ(Eigen::Vector3d(0.1, -0.05, 0.0)).toRotationMatrix() * g_L_true * 1.05;  // ~6 deg and 5 % off
  std::string why;
  ASSERT_TRUE(RefineGravity(in.frames, in.p_BC, 9.81, 4, &a, &why)) << why;
  EXPECT_LT(std::acos(std::min(1.0, a.g_L.normalized().dot(g_L_true.normalized()))), 0.05 * M_PI / 180);
}

TEST(LinearAlignment, RejectsMissingImu) {
  ExactInputs in = MakeExactInputs(Eigen::Vector3d::Zero(), 1.0);
  in.frames[4].imu_from_prev = nullptr;
  Alignment a;
  std::string why;
  EXPECT_FALSE(LinearAlignment(in.frames, in.p_BC, 9.81, 1.0, &a, &why));
  EXPECT_FALSE(why.empty());
}

TEST(TangentBasis, IsOrthonormalAndOrthogonalToN) {
  for (const Eigen::Vector3d& n :
       {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.3, -0.4, 0.5).normalized()}) {
    Eigen::Vector3d b1, b2;
    TangentBasis(n, &b1, &b2);
    EXPECT_NEAR(b1.norm(), 1.0, 1e-12);
    EXPECT_NEAR(b2.norm(), 1.0, 1e-12);
    EXPECT_NEAR(b1.dot(b2), 0.0, 1e-12);
    EXPECT_NEAR(b1.dot(n), 0.0, 1e-12);
    EXPECT_NEAR(b2.dot(n), 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace vigil::estimator
