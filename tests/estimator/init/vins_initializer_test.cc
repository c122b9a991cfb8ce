#include "estimator/init/vins_initializer.h"

#include <gtest/gtest.h>

#include "core/so3.h"
#include "estimator/make_initializer.h"
#include "simulated_window.h"

namespace vigil::estimator {
namespace {

struct InitErrors {
  double gyro_bias_rel = 0.0;  // |b_g - b_g_true| / |b_g_true|
  double scale_rel = 0.0;      // |1 - (path length estimated / true)| over the window's first-last baseline
  double gravity_deg = 0.0;    // angle between estimated and true gravity in the first body frame
  double velocity_mps = 0.0;   // largest velocity error after rotating into the true world by the yaw offset
};

InitErrors Compare(const Dataset& data, const std::vector<InitFrame>& window, const InitResult& r) {
  InitErrors e;
  const NavState& t0 = testing::TruthAt(data, window.front().t_ns);
  const NavState& t1 = testing::TruthAt(data, window.back().t_ns);
  e.gyro_bias_rel = (r.states.front().b_g - t0.b_g).norm() / t0.b_g.norm();
  e.scale_rel =
      std::abs((r.states.back().p_W - r.states.front().p_W).norm() / (t1.p_W - t0.p_W).norm() - 1.0);
  const Eigen::Vector3d g_B_est = r.states.front().q_WB.conjugate() * Eigen::Vector3d(0, 0, -1);
  const Eigen::Vector3d g_B_true = t0.q_WB.conjugate() * Eigen::Vector3d(0, 0, -1);
  e.gravity_deg = std::acos(std::min(1.0, g_B_est.dot(g_B_true))) * 180 / M_PI;
  // Both worlds have gravity along -z: they differ by a yaw only.
  const Eigen::Matrix3d R_true_est =
      RotZ(YawOf(t0.q_WB.toRotationMatrix()) - YawOf(r.states.front().q_WB.toRotationMatrix()));
  for (std::size_t k = 0; k < window.size(); ++k) {
    const NavState& t = testing::TruthAt(data, window[k].t_ns);
    e.velocity_mps = std::max(e.velocity_mps, (R_true_est * r.states[k].v_W - t.v_W).norm());
  }
  return e;
}

TEST(VinsInitializer, IdealImuWithBiasesRecoversBiasScaleAndGravity) {
  const Eigen::Vector3d b_g(0.03, -0.02, 0.025), b_a(0.05, -0.05, 0.05);
  const Dataset data = sim::Simulate(testing::WindowSimOptions(0.0, b_g, b_a), 11);
  const auto window = testing::MakeWindow(data, 4, 11, ImuNoiseDensities{});
  VinsInitializer init(VinsInitOptions{}, data.camera, 9.81, 11);
  InitResult r;
  ASSERT_TRUE(init.TryInitialize(window, &r)) << r.failure_reason;
  ASSERT_EQ(r.states.size(), window.size());
  const InitErrors e = Compare(data, window, r);
  EXPECT_LT(e.gyro_bias_rel, 0.10);
  EXPECT_LT(e.scale_rel, 0.02);
  EXPECT_LT(e.gravity_deg, 1.0);
  EXPECT_LT(e.velocity_mps, 0.2);
  // World: gravity along -z, the first body at the origin with zero yaw.
  EXPECT_LT(r.states.front().p_W.norm(), 1e-9);
  EXPECT_NEAR(YawOf(r.states.front().q_WB.toRotationMatrix()), 0.0, 1e-9);
  for (std::size_t k = 0; k < window.size(); ++k) EXPECT_EQ(r.states[k].t_ns, window[k].t_ns);
  // The window's tracks are reconstructed as landmarks.
  EXPECT_GE(r.landmarks_W.size(), 20u);
}

TEST(VinsInitializer, PaperImuNoiseKeepsScaleAndGravityWithinTolerance) {
  for (uint64_t seed : {1, 2, 3}) {
    const Dataset data =
        sim::Simulate(testing::WindowSimOptions(1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), seed);
    const auto window = testing::MakeWindow(data, 2, 11, ImuNoiseDensities{});
    VinsInitializer init(VinsInitOptions{}, data.camera, 9.81, 11);
    InitResult r;
    ASSERT_TRUE(init.TryInitialize(window, &r)) << "seed " << seed << ": " << r.failure_reason;
    const InitErrors e = Compare(data, window, r);
    EXPECT_LT(e.scale_rel, 0.02) << "seed " << seed;
    EXPECT_LT(e.gravity_deg, 1.0) << "seed " << seed;
  }
}

TEST(VinsInitializer, FailsWithoutParallaxAndSaysWhy) {
  const Dataset data =
      sim::Simulate(testing::WindowSimOptions(0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), 1);
  auto window = testing::MakeWindow(data, 0, 11, ImuNoiseDensities{});
  for (auto& f : window) f.features_n = window.front().features_n;  // a camera that sees no motion
  VinsInitializer init(VinsInitOptions{}, data.camera, 9.81, 11);
  InitResult r;
  EXPECT_FALSE(init.TryInitialize(window, &r));
  EXPECT_NE(r.failure_reason.find("no reference frame"), std::string::npos) << r.failure_reason;
  EXPECT_TRUE(r.states.empty());
  EXPECT_TRUE(init.CanReinitialize());
}

TEST(VinsInitializer, WaitsForAFullWindow) {
  const Dataset data =
      sim::Simulate(testing::WindowSimOptions(0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), 1);
  const auto window = testing::MakeWindow(data, 2, 11, ImuNoiseDensities{});
  VinsInitializer init(VinsInitOptions{}, data.camera, 9.81, 12);
  InitResult r;
  EXPECT_FALSE(init.TryInitialize(window, &r));
  EXPECT_NE(r.failure_reason.find("window not full (11 of 12 frames)"), std::string::npos)
      << r.failure_reason;
}

TEST(MakeInitializer, VinsNeedsNoGroundTruth) {
  EstimatorOptions options;
  options.init = InitMode::kVins;
  EstimatorInput input;  // no ground truth
  const auto init = MakeInitializer(options, input);
  ASSERT_NE(init, nullptr);
  EXPECT_TRUE(init->CanReinitialize());
}

}  // namespace
}  // namespace vigil::estimator
