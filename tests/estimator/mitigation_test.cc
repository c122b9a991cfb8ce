// In-estimator mitigation: per-sample inflation in preintegration, clipped-sample detection, the chi-square
// gate and duplicated IMU timestamps.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "core/error.h"
#include "estimator/imu_gating.h"
#include "estimator/imu_interval.h"
#include "estimator/imu_trust.h"
#include "estimator/preintegration.h"

namespace vigil::estimator {
namespace {

ImuStream ConstantImu(int n, double rate_hz) {
  ImuStream imu(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    imu[k].t_ns = static_cast<int64_t>(std::llround(k * 1e9 / rate_hz));
    imu[k].w_B = Eigen::Vector3d(0.1, -0.2, 0.3);
    imu[k].a_B = Eigen::Vector3d(0.5, 0.1, 9.81);
  }
  return imu;
}

TEST(ChiSquareQuantileTest, MatchesTables) {
  // Published chi-square quantiles (15 dof: 0.95 -> 24.996, 0.99 -> 30.578, 0.999 -> 37.697; 1 dof 0.95 ->
  // 3.841).
  EXPECT_NEAR(ChiSquareQuantile(15, 0.95), 24.9958, 1e-3);
  EXPECT_NEAR(ChiSquareQuantile(15, 0.99), 30.5779, 1e-3);
  EXPECT_NEAR(ChiSquareQuantile(15, 0.999), 37.6973, 1e-3);
  EXPECT_NEAR(ChiSquareQuantile(1, 0.95), 3.8415, 1e-3);
}

TEST(PreintegrationMitigationTest, UnitScaleIsBitIdenticalAndInflationWidensCovariance) {
  const ImuStream imu = ConstantImu(41, 200.0);
  const ImuNoiseDensities noise;
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const Preintegration plain = PreintegrateInterval(imu, imu[0].t_ns, imu[40].t_ns, zero, zero, noise, 200.0);
  std::vector<double> ones(imu.size(), 1.0);
  const Preintegration unit =
      PreintegrateInterval(imu, imu[0].t_ns, imu[40].t_ns, zero, zero, noise, 200.0, &ones);
  EXPECT_EQ(plain.covariance(), unit.covariance());  // bit for bit
  EXPECT_EQ(plain.delta_p(), unit.delta_p());
  std::vector<double> scale = ones;
  scale[20] = 1e4;
  Preintegration inflated =
      PreintegrateInterval(imu, imu[0].t_ns, imu[40].t_ns, zero, zero, noise, 200.0, &scale);
  EXPECT_EQ(plain.delta_p(), inflated.delta_p());  // the deltas do not change, only their uncertainty
  const Matrix15d difference = inflated.covariance() - plain.covariance();
  EXPECT_GT(difference.diagonal().segment<3>(kDv).minCoeff(), 0.0);
  EXPECT_GT(difference.diagonal().segment<3>(kDtheta).minCoeff(), 0.0);
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Matrix15d>(difference).eigenvalues().minCoeff(),
            -1e-12 * difference.norm());
  // The scales are part of the steps: re-propagating reproduces the inflated covariance.
  const Matrix15d before = inflated.covariance();
  inflated.Repropagate(zero, zero);
  EXPECT_LT((inflated.covariance() - before).norm(), 1e-15 * before.norm());
  // One sample with scale s adds (s - 1) times its share: velocity variance of two half-weighted sample
  // contributions of dt^2 var_a / 4 each (doubled var, see preintegration.h) in each axis.
  const double dt = 1.0 / 200.0;
  const double var_a = 2.0 * noise.accel_noise_density * noise.accel_noise_density * 200.0;
  EXPECT_NEAR(difference(kDv + 2, kDv + 2), (1e4 - 1.0) * 2.0 * 0.25 * dt * dt * var_a,
              1e-3 * difference(kDv + 2, kDv + 2));
}

TEST(ImuTrustTest, FlagsAndClippedSamples) {
  ImuStream imu = ConstantImu(10, 200.0);
  imu[3].a_B.z() = 39.24;  // at +-4 g
  imu[5].w_B.x() = -34.9;  // at -2000 deg/s (34.907 rad/s) within the tolerance
  const std::vector<uint8_t> flagged = {0, 1, 0, 1, 0, 0, 0, 0, 0, 0};
  MitigationOptions options;
  EXPECT_TRUE(ComputeImuTrust(options, imu, flagged).variance_scale.empty());  // all off
  options.inflate.enabled = true;
  options.inflate.variance_factor = 100.0;
  ImuTrust trust = ComputeImuTrust(options, imu, flagged);
  ASSERT_EQ(trust.variance_scale.size(), imu.size());
  EXPECT_EQ(trust.inflated_samples, 2);
  EXPECT_EQ(trust.variance_scale[1], 100.0);
  EXPECT_EQ(trust.variance_scale[2], 1.0);
  options.saturation.enabled = true;
  options.saturation.accel_range_mps2 = 39.24;
  options.saturation.gyro_range_dps = 2000.0;
  options.saturation.variance_factor = 1e4;
  trust = ComputeImuTrust(options, imu, flagged);
  EXPECT_EQ(trust.clipped_samples, 2);
  EXPECT_EQ(trust.variance_scale[3], 1e4);  // flagged and clipped: the larger factor
  EXPECT_EQ(trust.variance_scale[5], 1e4);
  EXPECT_EQ(trust.variance_scale[4], 1.0);
}

}  // namespace
}  // namespace vigil::estimator
