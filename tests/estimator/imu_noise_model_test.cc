#include "estimator/imu_noise_model.h"

#include <cmath>

#include <gtest/gtest.h>

namespace vigil::estimator {
namespace {

ImuNoiseDensities Sensor() { return {0.015, 0.019, 1e-5, 1e-4}; }

TEST(ImuNoiseModel, MatchedIsTheSensorsOwn) {
  const ImuNoiseDensities d = ResolveImuNoise({}, Sensor(), 200.0);
  EXPECT_EQ(d.gyro_noise_density, 0.015);
  EXPECT_EQ(d.accel_noise_density, 0.019);
  EXPECT_EQ(d.gyro_bias_random_walk, 1e-5);
  EXPECT_EQ(d.accel_bias_random_walk, 1e-4);
}

TEST(ImuNoiseModel, PerSampleStdIsDensityTimesSqrtRate) {
  // The paper scenario's sensor at 200 Hz: acc 0.019 x sqrt(200) = 0.2687, gyro 0.015 x sqrt(200) = 0.2121.
  const ImuNoisePerSample p = PerSampleFromDensities(Sensor(), 200.0);
  EXPECT_NEAR(p.acc_n, 0.26870, 1e-5);
  EXPECT_NEAR(p.gyr_n, 0.21213, 1e-5);
  EXPECT_NEAR(p.acc_w, 1e-4 / std::sqrt(200.0), 1e-15);  // the bias step over one sample
  EXPECT_NEAR(p.gyr_w, 1e-5 / std::sqrt(200.0), 1e-15);
  const ImuNoiseDensities back = DensitiesFromPerSample(p, 200.0);
  EXPECT_NEAR(back.accel_noise_density, 0.019, 1e-15);
  EXPECT_NEAR(back.gyro_noise_density, 0.015, 1e-15);
  EXPECT_NEAR(back.accel_bias_random_walk, 1e-4, 1e-15);
  EXPECT_NEAR(back.gyro_bias_random_walk, 1e-5, 1e-15);
}

TEST(ImuNoiseModel, DensitiesTypedInAsPerSampleValuesAreSqrtRateTooSmall) {
  ImuNoiseModelOptions o;
  o.model = ImuNoiseModel::kDensitiesAsPerSample;
  const ImuNoiseDensities d = ResolveImuNoise(o, Sensor(), 200.0);
  EXPECT_NEAR(d.accel_noise_density, 0.019 / std::sqrt(200.0), 1e-15);
  EXPECT_NEAR(d.gyro_noise_density, 0.015 / std::sqrt(200.0), 1e-15);
  EXPECT_NEAR(PerSampleFromDensities(d, 200.0).acc_n, 0.019, 1e-15);
}

TEST(ImuNoiseModel, VinsEurocValuesArePerSample) {
  ImuNoiseModelOptions o;
  o.model = ImuNoiseModel::kVinsEuroc;
  const ImuNoisePerSample p = PerSampleFromDensities(ResolveImuNoise(o, Sensor(), 200.0), 200.0);
  EXPECT_NEAR(p.acc_n, 0.08, 1e-15);
  EXPECT_NEAR(p.gyr_n, 0.004, 1e-15);
  EXPECT_NEAR(p.acc_w, 4e-5, 1e-18);
  EXPECT_NEAR(p.gyr_w, 2e-6, 1e-18);
}

TEST(ImuNoiseModel, HandSetDensitiesAndPerSampleValues) {
  ImuNoiseModelOptions o;
  o.model = ImuNoiseModel::kDensities;
  o.densities.accel_noise_density = 0.5;
  EXPECT_EQ(ResolveImuNoise(o, Sensor(), 200.0).accel_noise_density, 0.5);
  o.model = ImuNoiseModel::kPerSample;
  o.per_sample.acc_n = 1.0;
  EXPECT_NEAR(ResolveImuNoise(o, Sensor(), 400.0).accel_noise_density, 1.0 / 20.0, 1e-15);
}

}  // namespace
}  // namespace vigil::estimator
