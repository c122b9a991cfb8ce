// The IMU noise model the estimator weights its IMU factors with (estimator.imu_noise), apart from the noise
// the sensor really has.
//
// The run layer passes the sensor's own continuous-time densities (EstimatorInput::imu_noise, from the
// scenario's imu.noise); this model says what the estimator believes:
//   matched                  the sensor's own densities (the default: a perfectly calibrated estimator);
//   densities                the *_density keys, continuous time (datasheet / Kalibr units);
//   per_sample               the VINS-Mono-style keys acc_n, gyr_n, acc_w, gyr_w, discrete per sample;
//   densities_as_per_sample  the sensor's densities typed in as per-sample values (a common mis-setting:
//                            the white noise then believed sqrt(rate_hz) times smaller than it is);
//   vins_euroc               VINS-Mono's shipped EuRoC values acc_n 0.08, gyr_n 0.004, acc_w 4e-5, gyr_w 2e-6
//                            as per-sample values.
// Conversion between per-sample values and densities at the IMU rate (dt = 1 / rate_hz):
//   white noise:        per-sample std = density x sqrt(rate_hz)   (a sample averages the noise over dt);
//   bias random walk:   per-sample std = density / sqrt(rate_hz)   (the std of the bias step over dt).
// VINS-Mono's acc_n / gyr_n enter its preintegration covariance as per-sample standard deviations although
// its configs call them densities (docs/references.md); its code also multiplies the bias-walk
// noise by dt once more, which this model does not copy (the bias-walk terms weigh little next to the white
// noise, which is what the mis-settings change by factors of 3 to 50).
#pragma once

#include "core/config.h"
#include "estimator/estimator_input.h"
#include "estimator/rest_noise.h"

namespace vigil::estimator {

enum class ImuNoiseModel { kMatched, kDensities, kPerSample, kDensitiesAsPerSample, kVinsEuroc };

inline const config::EnumNames<ImuNoiseModel>& ImuNoiseModelNames() {
  static const config::EnumNames<ImuNoiseModel> names = {
      {"matched", ImuNoiseModel::kMatched},
      {"densities", ImuNoiseModel::kDensities},
      {"per_sample", ImuNoiseModel::kPerSample},
      {"densities_as_per_sample", ImuNoiseModel::kDensitiesAsPerSample},
      {"vins_euroc", ImuNoiseModel::kVinsEuroc}};
  return names;
}

// Discrete per-sample standard deviations (VINS-Mono's acc_n, gyr_n, acc_w, gyr_w).
struct ImuNoisePerSample {
  double acc_n = 0.08;   // accelerometer white noise [m/s^2] per sample
  double gyr_n = 0.004;  // gyroscope white noise [rad/s] per sample
  double acc_w = 4e-5;   // accelerometer bias step [m/s^2] per sample
  double gyr_w = 2e-6;   // gyroscope bias step [rad/s] per sample
};

struct ImuNoiseModelOptions {
  ImuNoiseModel model = ImuNoiseModel::kMatched;
  ImuNoiseDensities densities;   // model densities
  ImuNoisePerSample per_sample;  // model per_sample (defaults: VINS-Mono's EuRoC values)
  RestNoiseOptions at_rest;  // the white noise measured at the start's rest raises the model (rest_noise.h)

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Enum("model", model, ImuNoiseModelNames(),
           "matched: the sensor's own densities; densities / per_sample: the keys below; "
           "densities_as_per_sample: the sensor's densities used as per-sample values (mis-set); vins_euroc: "
           "VINS-Mono's EuRoC acc_n 0.08, gyr_n 0.004, acc_w 4e-5, gyr_w 2e-6 per sample (mis-set)");
    v.Field("gyro_noise_density", densities.gyro_noise_density,
            "model densities: gyro white noise [rad/s/sqrt(Hz)]", Bounds::Positive());
    v.Field("accel_noise_density", densities.accel_noise_density,
            "model densities: accelerometer white noise [m/s^2/sqrt(Hz)]", Bounds::Positive());
    v.Field("gyro_bias_random_walk", densities.gyro_bias_random_walk,
            "model densities: gyro bias random walk [rad/s^2/sqrt(Hz)]", Bounds::Positive());
    v.Field("accel_bias_random_walk", densities.accel_bias_random_walk,
            "model densities: accelerometer bias random walk [m/s^3/sqrt(Hz)]", Bounds::Positive());
    v.Field("acc_n", per_sample.acc_n, "model per_sample: accelerometer white noise std per sample [m/s^2]",
            Bounds::Positive());
    v.Field("gyr_n", per_sample.gyr_n, "model per_sample: gyro white noise std per sample [rad/s]",
            Bounds::Positive());
    v.Field("acc_w", per_sample.acc_w, "model per_sample: accelerometer bias step std per sample [m/s^2]",
            Bounds::Positive());
    v.Field("gyr_w", per_sample.gyr_w, "model per_sample: gyro bias step std per sample [rad/s]",
            Bounds::Positive());
    v.Section("at_rest", at_rest, "the IMU's white noise measured at the start's rest");
  }
};

// Per-sample values <-> densities at `rate_hz` (see above).
ImuNoiseDensities DensitiesFromPerSample(const ImuNoisePerSample& per_sample, double rate_hz);
ImuNoisePerSample PerSampleFromDensities(const ImuNoiseDensities& densities, double rate_hz);

// The densities the estimator uses: `sensor` (the sensor's own) for matched, else the model's.
ImuNoiseDensities ResolveImuNoise(const ImuNoiseModelOptions& options, const ImuNoiseDensities& sensor,
                                  double rate_hz);

}  // namespace vigil::estimator
