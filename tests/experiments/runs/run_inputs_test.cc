#include "experiments/runs/run_inputs.h"

#include <gtest/gtest.h>

#include "sim/simulator.h"

namespace vigil::experiments {
namespace {

TEST(RunInputs, GroundTruthAtCameraRateMatchesTheTrajectory) {
  const RunConfig config = LoadRunConfig("", {"duration_s=4", "imu.noise.enabled=false"});
  const Dataset data = sim::Simulate(config.sim, config.seed);
  const Trajectory gt = GroundTruthAtFrames(data.groundtruth, data.frames);
  ASSERT_EQ(gt.size(), data.frames.size());  // every frame lies inside the ground truth's span
  EXPECT_EQ(gt.size(), 121u);                // 4 s at 30 Hz, both ends included
  for (std::size_t k = 0; k < gt.size(); ++k) EXPECT_EQ(gt[k].t_ns, data.frames[k].t_ns);
  // Reference ellipse: p(t) = (15 cos(Kt) + 5, 20 sin(Kt) + 5, sin(K1 K t) + 5), K = pi/10, K1 = 10. Linear
  // interpolation between 5 ms samples is good to well below a millimetre.
  for (const StampedPose& p : gt) {
    const double t = NsToS(p.t_ns), K = M_PI / 10;
    const Eigen::Vector3d expected(15 * std::cos(K * t) + 5, 20 * std::sin(K * t) + 5,
                                   std::sin(10 * K * t) + 5);
    EXPECT_LT((p.p_W - expected).norm(), 1e-4) << t;
  }
  // A frame outside the ground truth is left out.
  std::vector<CameraFrame> frames = data.frames;
  frames.push_back({data.groundtruth.back().t_ns + 1'000'000, {}});
  EXPECT_EQ(GroundTruthAtFrames(data.groundtruth, frames).size(), data.frames.size());
}

TEST(RunInputs, EstimatorInputCarriesTheConfiguredNoiseModel) {
  const RunConfig config =
      LoadRunConfig("", {"duration_s=2", "seed=7", "imu.noise.accel_noise_density=0.05", "gravity_mps2=9.8"});
  const Dataset data = sim::Simulate(config.sim, config.seed);
  const estimator::EstimatorInput in = MakeEstimatorInput(config, data, data.imu_clean);
  EXPECT_EQ(in.imu_noise.accel_noise_density, 0.05);
  EXPECT_EQ(in.imu_noise.gyro_noise_density, config.sim.imu.noise.gyro_noise_density);
  EXPECT_EQ(in.imu_noise.accel_bias_random_walk, config.sim.imu.noise.accel_bias_random_walk);
  EXPECT_EQ(in.gravity_mps2, 9.8);
  EXPECT_EQ(in.seed, 7u);
  EXPECT_EQ(in.frames.size(), data.frames.size());
  EXPECT_EQ(in.imu.size(), data.imu_clean.size());
  EXPECT_EQ(in.imu[10].a_B, data.imu_clean[10].a_B);
  EXPECT_EQ(in.groundtruth.size(), data.groundtruth.size());
  EXPECT_EQ(in.camera.fx, data.camera.fx);
}

}  // namespace
}  // namespace vigil::experiments
