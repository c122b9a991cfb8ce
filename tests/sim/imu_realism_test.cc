// The realistic-IMU options: bias at switch-on, vibration, and the sensor-class presets.
#include <cmath>
#include <complex>
#include <cstdio>

#include <gtest/gtest.h>

#include "experiments/runs/run_config.h"
#include "sim/imu_presets.h"
#include "sim/imu_synthesizer.h"
#include "sim/vibration.h"
#include "tests/core/test_util.h"

namespace vigil::sim {
namespace {

class AtRest final : public TrajectoryModel {
 public:
  TrajectoryState StateAt(double) const override { return {}; }
};

ImuOptions Quiet() {
  ImuOptions o;
  o.noise.gyro_noise_density = 0.0;
  o.noise.accel_noise_density = 0.0;
  o.noise.gyro_bias_random_walk = 0.0;
  o.noise.accel_bias_random_walk = 0.0;
  return o;
}

// Over 400 seeds (1,200 draws per sensor) the switch-on biases have the configured spread (the sample std's
// relative standard error is 2 %, the bound 8 %) and zero mean; one seed gives one bias, held by every
// sample.
TEST(SwitchOnBias, HasTheConfiguredSpreadOverSeeds) {
  ImuOptions o = Quiet();
  o.noise.switch_on_gyro_bias_std = 0.02;
  o.noise.switch_on_accel_bias_std = 0.1;
  o.noise.initial_gyro_bias = {0.5, 0.0, 0.0};
  std::vector<double> g, a;
  for (uint64_t seed = 1; seed <= 400; ++seed) {
    const ImuSynthesis s = SynthesizeImu(AtRest(), o, 0.05, 9.81, seed);
    const Eigen::Vector3d b_g = s.groundtruth.front().b_g - Eigen::Vector3d(0.5, 0, 0);
    EXPECT_EQ(s.groundtruth.back().b_g, s.groundtruth.front().b_g);  // no random walk: held
    EXPECT_LT((s.imu.back().w_B - s.groundtruth.front().b_g).norm(), 1e-15);
    for (int i = 0; i < 3; ++i) {
      g.push_back(b_g[i]);
      a.push_back(s.groundtruth.front().b_a[i]);
    }
  }
  const auto stats = [](const std::vector<double>& x, double* mean, double* std) {
    *mean = 0;
    for (double v : x) *mean += v / static_cast<double>(x.size());
    double ss = 0;
    for (double v : x) ss += (v - *mean) * (v - *mean);
    *std = std::sqrt(ss / static_cast<double>(x.size() - 1));
  };
  double mean_g, std_g, mean_a, std_a;
  stats(g, &mean_g, &std_g);
  stats(a, &mean_a, &std_a);
  std::printf("switch-on bias over 400 seeds: gyro mean %.3g std %.4g; accel mean %.3g std %.4g\n", mean_g,
              std_g, mean_a, std_a);
  EXPECT_NEAR(std_g / 0.02, 1.0, 0.08);
  EXPECT_NEAR(std_a / 0.1, 1.0, 0.08);
  EXPECT_LT(std::abs(mean_g), 4 * 0.02 / std::sqrt(1200.0));
  EXPECT_LT(std::abs(mean_a), 4 * 0.1 / std::sqrt(1200.0));
}

// The switch-on draw has its own stream: the white noise and the random walk of a run do not change.
TEST(SwitchOnBias, LeavesTheOtherStreamsUnchanged) {
  const ImuOptions plain;
  ImuOptions spread = plain;
  spread.noise.switch_on_gyro_bias_std = 0.01;
  spread.noise.switch_on_accel_bias_std = 0.05;
  const ImuSynthesis a = SynthesizeImu(AtRest(), plain, 2.0, 9.81, 5),
                     b = SynthesizeImu(AtRest(), spread, 2.0, 9.81, 5);
  const Eigen::Vector3d d_g = b.groundtruth[0].b_g - a.groundtruth[0].b_g;
  EXPECT_GT(d_g.norm(), 0.0);
  for (std::size_t k = 0; k < a.imu.size(); k += 37) {
    EXPECT_LT((b.imu[k].w_B - a.imu[k].w_B - d_g).norm(), 1e-12);
    EXPECT_LT((b.groundtruth[k].b_g - a.groundtruth[k].b_g - d_g).norm(), 1e-12);
  }
}

// Power of x (sampled at rate_hz) in the band [f_lo, f_hi), by a direct DFT on a 0.25 Hz grid.
double BandPower(const std::vector<double>& x, double rate_hz, double f_lo, double f_hi) {
  double p = 0;
  for (double f = f_lo; f < f_hi; f += 0.25) {
    std::complex<double> s = 0;
    for (std::size_t k = 0; k < x.size(); ++k)
      s += x[k] * std::polar(1.0, -2.0 * 3.14159265358979323846 * f * static_cast<double>(k) / rate_hz);
    p += std::norm(s);
  }
  return p;
}

// At rest with no noise, the IMU reads gravity plus the vibration: each axis has the configured rms, and its
// spectrum sits in the configured band (above half the rate it folds back, as a sampled sensor aliases).
// Measured: 94-99.5 % of the power within 2.5 Hz of the band's centre.
TEST(Vibration, HasTheConfiguredRmsAndSpectralPeak) {
  for (const auto& [f_hz, seen_hz] : {std::pair{30.0, 30.0}, std::pair{150.0, 50.0}}) {
    ImuOptions o = Quiet();
    o.vibration.frequency_hz = f_hz;
    o.vibration.bandwidth_hz = 4.0;
    o.vibration.accel_rms_mps2 = 1.2;
    o.vibration.gyro_rms_radps = 0.06;
    const ImuSynthesis s = SynthesizeImu(AtRest(), o, 20.0, 9.81, 3);
    std::vector<double> wx, az;
    double ss_w = 0, ss_a = 0;
    for (const ImuSample& m : s.imu) {
      wx.push_back(m.w_B.x());
      az.push_back(m.a_B.z() - 9.81);
      ss_w += m.w_B.squaredNorm() / 3.0;
      ss_a += (m.a_B - Eigen::Vector3d(0, 0, 9.81)).squaredNorm() / 3.0;
    }
    const double n = static_cast<double>(s.imu.size());
    EXPECT_NEAR(std::sqrt(ss_w / n) / 0.06, 1.0, 0.15) << f_hz;
    EXPECT_NEAR(std::sqrt(ss_a / n) / 1.2, 1.0, 0.15) << f_hz;
    for (const std::vector<double>* x : {&wx, &az}) {
      const double in_band = BandPower(*x, 200.0, seen_hz - 2.5, std::min(seen_hz + 2.5, 100.0));
      const double total = BandPower(*x, 200.0, 0.0, 100.0);
      std::printf("vibration at %.0f Hz: %.1f %% of the power within 2.5 Hz of %.0f Hz\n", f_hz,
                  100 * in_band / total, seen_hz);
      EXPECT_GT(in_band / total, 0.9) << f_hz;  // the rest is the leakage of a 20 s rectangular window
      EXPECT_LT(BandPower(*x, 200.0, 12.5, 17.5) / total, 0.01) << f_hz;  // far from the band: nothing
    }
    // The ground truth does not vibrate.
    EXPECT_EQ(s.groundtruth[100].p_W, Eigen::Vector3d::Zero());
  }
}

TEST(Vibration, IsOffByDefaultAndDeterministic) {
  const ImuOptions plain;
  EXPECT_FALSE(plain.vibration.enabled());
  ImuVibrationOptions v;
  v.frequency_hz = 80;
  v.accel_rms_mps2 = 1;
  EXPECT_TRUE(v.enabled());
  Eigen::Vector3d w1, a1, w2, a2, w3, a3;
  Vibration(v, 1).At(0.37, &w1, &a1);
  Vibration(v, 1).At(0.37, &w2, &a2);
  Vibration(v, 2).At(0.37, &w3, &a3);
  EXPECT_EQ(a1, a2);
  EXPECT_NE(a1, a3);
  EXPECT_EQ(w1, Eigen::Vector3d::Zero());  // no gyro amplitude
}

TEST(ImuPreset, SetsTheDefaultsOfTheNoiseKeysWhichTheConfigStillOverrides) {
  testing::TempDir tmp;
  const experiments::RunConfig mpu =
      experiments::LoadRunConfig(tmp.File("mpu.yaml", "imu:\n  preset: mpu6050\n"));
  EXPECT_EQ(mpu.sim.imu.preset, ImuPreset::kMpu6050);
  EXPECT_NEAR(mpu.sim.imu.noise.gyro_noise_density, 8.7266e-5, 1e-9);     // 0.005 deg/s/sqrt(Hz)
  EXPECT_NEAR(mpu.sim.imu.noise.accel_noise_density, 3.9227e-3, 1e-7);    // 400 ug/sqrt(Hz)
  EXPECT_NEAR(mpu.sim.imu.noise.switch_on_gyro_bias_std, 0.34907, 1e-5);  // 20 deg/s
  const experiments::RunConfig bmi = experiments::LoadRunConfig(
      tmp.File("bmi.yaml", "imu:\n  preset: bmi088\n  noise:\n    gyro_noise_density: 0.5\n"));
  EXPECT_EQ(bmi.sim.imu.noise.gyro_noise_density, 0.5);                 // written in the config: kept
  EXPECT_NEAR(bmi.sim.imu.noise.accel_noise_density, 1.7162e-3, 1e-7);  // 175 ug/sqrt(Hz)
  const experiments::RunConfig adis =
      experiments::LoadRunConfig(tmp.File("none.yaml", "seed: 1\n"), {"imu.preset=adis16448"});
  EXPECT_EQ(adis.sim.imu.noise.gyro_noise_density, 1.6968e-4);
  EXPECT_EQ(adis.sim.imu.noise.accel_bias_random_walk, 3.0e-3);
  // No preset: vigil's own defaults, untouched.
  const experiments::RunConfig none = experiments::LoadRunConfig(tmp.File("plain.yaml", "seed: 1\n"));
  const ImuNoiseOptions defaults;
  EXPECT_EQ(none.sim.imu.noise.gyro_noise_density, defaults.gyro_noise_density);
  EXPECT_EQ(none.sim.imu.noise.switch_on_gyro_bias_std, 0.0);
  ImuOptions o;
  ApplyImuPreset(ImuPreset::kNone, &o);
  EXPECT_EQ(o.noise.accel_noise_density, defaults.accel_noise_density);
}

}  // namespace
}  // namespace vigil::sim
