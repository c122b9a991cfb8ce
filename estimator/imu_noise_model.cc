#include "estimator/imu_noise_model.h"

#include <cmath>

namespace vigil::estimator {

ImuNoiseDensities DensitiesFromPerSample(const ImuNoisePerSample& per_sample, double rate_hz) {
  const double root = std::sqrt(rate_hz);
  ImuNoiseDensities d;
  d.accel_noise_density = per_sample.acc_n / root;
  d.gyro_noise_density = per_sample.gyr_n / root;
  d.accel_bias_random_walk = per_sample.acc_w * root;
  d.gyro_bias_random_walk = per_sample.gyr_w * root;
  return d;
}

ImuNoisePerSample PerSampleFromDensities(const ImuNoiseDensities& densities, double rate_hz) {
  const double root = std::sqrt(rate_hz);
  ImuNoisePerSample p;
  p.acc_n = densities.accel_noise_density * root;
  p.gyr_n = densities.gyro_noise_density * root;
  p.acc_w = densities.accel_bias_random_walk / root;
  p.gyr_w = densities.gyro_bias_random_walk / root;
  return p;
}

ImuNoiseDensities ResolveImuNoise(const ImuNoiseModelOptions& options, const ImuNoiseDensities& sensor,
                                  double rate_hz) {
  switch (options.model) {
    case ImuNoiseModel::kDensities:
      return options.densities;
    case ImuNoiseModel::kPerSample:
      return DensitiesFromPerSample(options.per_sample, rate_hz);
    case ImuNoiseModel::kDensitiesAsPerSample:
      return DensitiesFromPerSample({sensor.accel_noise_density, sensor.gyro_noise_density,
                                     sensor.accel_bias_random_walk, sensor.gyro_bias_random_walk},
                                    rate_hz);
    case ImuNoiseModel::kVinsEuroc:
      return DensitiesFromPerSample(ImuNoisePerSample{}, rate_hz);
    case ImuNoiseModel::kMatched:
      break;
  }
  return sensor;
}

}  // namespace vigil::estimator
