#include "estimator/init_diagnosis.h"

#include <random>

#include <gtest/gtest.h>

#include "estimator/run_estimator.h"

#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// A simulated recording frozen at its first pose: the IMU reads gravity (plus white noise), every landmark
// is seen where it was at the start (plus 0.3 px of pixel noise). The sensor times are the simulation's.
EstimatorInput StationaryInput(double duration_s) {
  sim::SimOptions options;
  options.duration_s = duration_s;
  const Dataset data = sim::Simulate(options, 4);
  EstimatorInput input = testing::InputFromSimulation(options, data, 4);
  const NavState& x0 = data.groundtruth.front();
  std::mt19937_64 rng(7);
  std::normal_distribution<double> gyro(0.0, 0.002), accel(0.0, 0.02), pixel(0.0, 0.3);
  for (ImuSample& s : input.imu) {
    s.w_B = x0.b_g + Eigen::Vector3d(gyro(rng), gyro(rng), gyro(rng));
    s.a_B = x0.q_WB.conjugate() * Eigen::Vector3d(0.0, 0.0, input.gravity_mps2) + x0.b_a +
            Eigen::Vector3d(accel(rng), accel(rng), accel(rng));
  }
  const Eigen::Isometry3d T_WC = [&] {
    Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
    T_WB.linear() = x0.q_WB.toRotationMatrix();
    T_WB.translation() = x0.p_W;
    return T_WB * input.camera.T_BC_iso();
  }();
  for (CameraFrame& frame : input.frames) {
    frame.features.clear();
    for (const Landmark& l : data.landmarks) {
      Eigen::Vector2d uv;
      if (!input.camera.Project(T_WC.inverse() * l.p_W, &uv)) continue;
      frame.features.push_back({l.id, uv + Eigen::Vector2d(pixel(rng), pixel(rng))});
    }
  }
  input.groundtruth.clear();  // vins never reads it
  return input;
}

TEST(InitDiagnosis, AStationaryRecordingSaysThePlatformDidNotMove) {
  const EstimatorInput input = StationaryInput(4.0);
  ASSERT_GT(input.frames.front().features.size(), 20u);  // more than vins.min_correspondences
  EstimatorOptions options;
  options.init = InitMode::kVins;
  options.zero_velocity.static_init = false;  // the visual-inertial initializer alone cannot start here
  const EstimatorResult result = RunEstimator(options, input);
  EXPECT_FALSE(result.ok);
  EXPECT_TRUE(std::isnan(result.initialized_at_s));
  EXPECT_NE(result.failure_reason.find("never initialized: the platform did not move"), std::string::npos)
      << result.failure_reason;
  EXPECT_NE(result.failure_reason.find("last attempt: "), std::string::npos) << result.failure_reason;

  // With the static start (the default) the same still recording starts with its first window: 16 frames
  // solved at 10 Hz.
  options.zero_velocity.static_init = true;
  const EstimatorResult still = RunEstimator(options, input);
  EXPECT_TRUE(still.ok) << still.failure_reason;
  EXPECT_LE(still.initialized_at_s, 1.55);

  const InitEvidence e = MeasureInitEvidence(input, input.imu);
  EXPECT_EQ(e.frames, static_cast<int>(input.frames.size()));
  EXPECT_LT(e.max_displacement_px, kStationaryDisplacement_px);
  EXPECT_LT(e.gyro_std_radps, 0.01);
}

TEST(InitDiagnosis, AMovingRecordingIsNotCalledStationary) {
  sim::SimOptions options;
  options.duration_s = 3.0;
  const Dataset data = sim::Simulate(options, 5);
  const EstimatorInput input = testing::InputFromSimulation(options, data, 5);
  const InitEvidence e = MeasureInitEvidence(input, input.imu);
  EXPECT_GT(e.max_displacement_px, 5 * kStationaryDisplacement_px);
  EXPECT_EQ(DiagnoseNoInitialization(EstimatorOptions{}, e, 11, "sfm: no reference frame (best: 3 shared)")
                .rfind("not enough motion or parallax", 0),
            0u);
}

TEST(InitDiagnosis, NamesTheFirstMissingIngredient) {
  const EstimatorOptions options;
  InitEvidence e;
  EXPECT_EQ(DiagnoseNoInitialization(options, e, 11, "").rfind("no camera frame", 0), 0u);
  e.frames = 5;
  EXPECT_EQ(DiagnoseNoInitialization(options, e, 11, "").rfind("too few camera frames (5 ", 0), 0u);
  e.frames = 40;
  e.max_features = options.vins.min_correspondences;
  EXPECT_EQ(DiagnoseNoInitialization(options, e, 11, "x").rfind("too few features", 0), 0u);
  e.max_features = 100;
  e.max_displacement_px = 50.0;
  EXPECT_EQ(
      DiagnoseNoInitialization(options, e, 11, "linear alignment is singular").rfind("IMU excitation", 0),
      0u);
  EXPECT_EQ(DiagnoseNoInitialization(options, e, 11, "sfm: bundle adjustment failed: x")
                .rfind("structure from motion failed", 0),
            0u);
}

}  // namespace
}  // namespace vigil::estimator
