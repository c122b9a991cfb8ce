#include "sim/imu_synthesizer.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/so3.h"
#include "sim/ellipse_trajectory.h"
#include "sim/rescue_trajectory.h"
#include "tests/sim/midpoint_integration.h"

namespace vigil::sim {
namespace {

ImuOptions Ideal(double rate_hz) {
  ImuOptions o;
  o.rate_hz = rate_hz;
  o.noise.enabled = false;
  return o;
}

TEST(ImuSynthesizer, SampleTimes) {
  const auto t = ImuSampleTimes(200.0, 20.0);
  ASSERT_EQ(t.size(), 4001u);
  EXPECT_EQ(t[1], 5'000'000);
  EXPECT_EQ(t.back(), 20'000'000'000);
  EXPECT_EQ(ImuSampleTimes(300.0, 1.0)[1], 3'333'333);
}

TEST(ImuSynthesizer, AtRestReadsGravityOnZ) {
  class Still final : public TrajectoryModel {
   public:
    TrajectoryState StateAt(double) const override { return {}; }
  };
  const ImuSynthesis s = SynthesizeImu(Still(), Ideal(100.0), 1.0, 9.81, 1);
  EXPECT_EQ(s.imu[7].a_B, Eigen::Vector3d(0, 0, 9.81));
  EXPECT_EQ(s.imu[7].w_B, Eigen::Vector3d::Zero());
}

// With noise off, the midpoint rule (the propagation of the paper and of VINS-Mono) reproduces the ground
// truth up to its own truncation error, which is O(dt^2) globally: the error must be small over the whole 20
// s and shrink about 4x when the rate doubles. Any inconsistency between the synthesized IMU and the
// trajectory (a sign, a frame, a missing term) would instead give an error that does not shrink with dt.
TEST(ImuSynthesizer, IdealImuIntegratesBackToGroundTruth) {
  const EllipseTrajectory ellipse;
  const IntegrationError e200 = IntegrateMidpoint(SynthesizeImu(ellipse, Ideal(200.0), 20.0, 9.81, 1), 9.81);
  const IntegrationError e400 = IntegrateMidpoint(SynthesizeImu(ellipse, Ideal(400.0), 20.0, 9.81, 1), 9.81);
  const IntegrationError e800 = IntegrateMidpoint(SynthesizeImu(ellipse, Ideal(800.0), 20.0, 9.81, 1), 9.81);
  // At 200 Hz over the 119 m loop the measured maxima are 1.3 mm, 0.13 mm/s and 2.3e-6 rad; the bounds leave
  // a factor of 3 (an error in the IMU model, e.g. a wrong gravity sign or frame, gives metres).
  EXPECT_LT(e200.p_m, 4e-3);
  EXPECT_LT(e200.v_mps, 4e-4);
  EXPECT_LT(e200.rot_rad, 7e-6);
  for (const auto& [coarse, fine] : {std::pair{e200, e400}, std::pair{e400, e800}}) {
    EXPECT_NEAR(coarse.p_m / fine.p_m, 4.0, 0.4);
    EXPECT_NEAR(coarse.v_mps / fine.v_mps, 4.0, 0.4);
    EXPECT_NEAR(coarse.rot_rad / fine.rot_rad, 4.0, 0.4);
  }
  std::printf(
      "midpoint max error over 20 s: 200 Hz p %.3g m v %.3g m/s R %.3g rad; 400 Hz p %.3g v %.3g R %.3g; "
      "800 Hz p %.3g v %.3g R %.3g\n",
      e200.p_m, e200.v_mps, e200.rot_rad, e400.p_m, e400.v_mps, e400.rot_rad, e800.p_m, e800.v_mps,
      e800.rot_rad);
}

// The same property on the rescue course (C2 pieces, steps and bumps): still O(dt^2). Measured at 200 Hz:
// 3 cm over the 36 m loop (the 0.3 s bumps have large higher derivatives), 8 mm at 400 Hz.
TEST(ImuSynthesizer, IdealImuIntegratesBackOnTheRescueCourse) {
  const RescueTrajectory course;
  const double T = RescueTrajectory::kLoopPeriodS;
  const IntegrationError e200 = IntegrateMidpoint(SynthesizeImu(course, Ideal(200.0), T, 9.81, 1), 9.81);
  const IntegrationError e400 = IntegrateMidpoint(SynthesizeImu(course, Ideal(400.0), T, 9.81, 1), 9.81);
  std::printf("rescue midpoint max error over %.0f s: 200 Hz p %.3g m v %.3g m/s R %.3g rad; 400 Hz p %.3g\n",
              T, e200.p_m, e200.v_mps, e200.rot_rad, e400.p_m);
  EXPECT_LT(e200.p_m, 6e-2);
  EXPECT_LT(e200.rot_rad, 3e-5);
  EXPECT_NEAR(e200.p_m / e400.p_m, 4.0, 0.6);
  EXPECT_NEAR(e200.rot_rad / e400.rot_rad, 4.0, 0.6);
}

double SampleStd(const std::vector<double>& x) {
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
  return std::sqrt(ss / static_cast<double>(x.size() - 1));
}

// imu - ideal = bias + white noise. With 12003 draws per sensor the sample std has a relative standard error
// of 1/sqrt(2 N) = 0.65%: a 3% bound is more than 4 standard errors.
TEST(ImuSynthesizer, NoiseAndBiasRandomWalkHaveTheConfiguredStatistics) {
  const EllipseTrajectory ellipse;
  ImuOptions o;  // reference densities, 200 Hz
  const double dt = 1.0 / o.rate_hz;
  const ImuSynthesis noisy = SynthesizeImu(ellipse, o, 20.0, 9.81, 7);
  const ImuSynthesis ideal = SynthesizeImu(ellipse, Ideal(o.rate_hz), 20.0, 9.81, 7);
  std::vector<double> n_g, n_a, db_g, db_a;
  for (std::size_t k = 0; k < noisy.imu.size(); ++k) {
    const NavState& gt = noisy.groundtruth[k];
    const Eigen::Vector3d white_g = noisy.imu[k].w_B - ideal.imu[k].w_B - gt.b_g;
    const Eigen::Vector3d white_a = noisy.imu[k].a_B - ideal.imu[k].a_B - gt.b_a;
    for (int i = 0; i < 3; ++i) {
      n_g.push_back(white_g[i]);
      n_a.push_back(white_a[i]);
      if (k + 1 < noisy.imu.size()) {
        db_g.push_back(noisy.groundtruth[k + 1].b_g[i] - gt.b_g[i]);
        db_a.push_back(noisy.groundtruth[k + 1].b_a[i] - gt.b_a[i]);
      }
    }
  }
  EXPECT_EQ(noisy.groundtruth[0].b_g, Eigen::Vector3d::Zero());
  EXPECT_NEAR(SampleStd(n_g) / (o.noise.gyro_noise_density / std::sqrt(dt)), 1.0, 0.03);
  EXPECT_NEAR(SampleStd(n_a) / (o.noise.accel_noise_density / std::sqrt(dt)), 1.0, 0.03);
  EXPECT_NEAR(SampleStd(db_g) / (o.noise.gyro_bias_random_walk * std::sqrt(dt)), 1.0, 0.03);
  EXPECT_NEAR(SampleStd(db_a) / (o.noise.accel_bias_random_walk * std::sqrt(dt)), 1.0, 0.03);
  // Ground truth poses do not depend on the noise.
  EXPECT_EQ(noisy.groundtruth[1234].p_W, ideal.groundtruth[1234].p_W);
}

// The ground-truth biases are exactly those in effect in each sample.
TEST(ImuSynthesizer, GroundTruthBiasIsTheBiasInTheSample) {
  const EllipseTrajectory ellipse;
  ImuOptions o;
  o.noise.gyro_noise_density = 0.0;
  o.noise.accel_noise_density = 0.0;
  o.noise.gyro_bias_random_walk = 1e-2;
  o.noise.accel_bias_random_walk = 1e-1;
  o.noise.initial_gyro_bias = {0.01, -0.02, 0.03};
  o.noise.initial_accel_bias = {0.1, 0.2, -0.3};
  const ImuSynthesis biased = SynthesizeImu(ellipse, o, 5.0, 9.81, 3);
  const ImuSynthesis ideal = SynthesizeImu(ellipse, Ideal(o.rate_hz), 5.0, 9.81, 3);
  for (std::size_t k = 0; k < biased.imu.size(); ++k) {
    EXPECT_LT((biased.imu[k].w_B - ideal.imu[k].w_B - biased.groundtruth[k].b_g).norm(), 1e-12);
    EXPECT_LT((biased.imu[k].a_B - ideal.imu[k].a_B - biased.groundtruth[k].b_a).norm(), 1e-12);
  }
  EXPECT_EQ(biased.groundtruth[0].b_g, Eigen::Vector3d(0.01, -0.02, 0.03));
  EXPECT_EQ(biased.groundtruth[0].b_a, Eigen::Vector3d(0.1, 0.2, -0.3));
  EXPECT_GT((biased.groundtruth.back().b_a - biased.groundtruth[0].b_a).norm(), 1e-3);
}

TEST(ImuSynthesizer, SeedsGiveIndependentNoise) {
  const EllipseTrajectory ellipse;
  const ImuOptions o;
  const ImuSynthesis a = SynthesizeImu(ellipse, o, 1.0, 9.81, 1), b = SynthesizeImu(ellipse, o, 1.0, 9.81, 1),
                     c = SynthesizeImu(ellipse, o, 1.0, 9.81, 2);
  for (std::size_t k = 0; k < a.imu.size(); ++k) {
    EXPECT_EQ(a.imu[k].a_B, b.imu[k].a_B);
    EXPECT_NE(a.imu[k].a_B, c.imu[k].a_B);
  }
}

}  // namespace
}  // namespace vigil::sim
