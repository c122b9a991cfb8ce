// The IMU's white noise measured while the platform stands still at the start (estimator.imu_noise.at_rest;
// docs/estimator.md, "The IMU noise measured at rest"). This is vigil's rule, not VINS-Mono's, which weighs
// the IMU with the configured values only.
//
// A datasheet's noise densities describe the sensor on a bench. Mounted on a vehicle, the IMU also measures
// the vibration of rotors, motors or tracks. On EuRoC V1_01 the samples of the 5 s stationary start scatter
// 5-10 times as much as the datasheet's densities say, at every averaging time from 5 ms to 0.25 s, and an
// estimator that trusts the datasheet weighs its IMU factors far too much. The rule:
//   rest      the first run of consecutive camera frames, at least min_rest_s long, that the image test
//             of the static start (zero_velocity_detector.h, at static_init_pixel_std_px) finds stationary,
//             at the quantile `probability` (a single noisy interval must not end the rest): each frame
//             against the one before it and against the rest's first frame, so that a slow motion, within
//             the noise at every interval, is no rest. It is the stand the static start stands on: at
//             zero_velocity.pixel_std_px (0.5 px) tracks of 1 px noise showed no rest, and the model kept
//             the datasheet's noise;
//   measure   over that rest, the Allan deviation at tau = the camera period: the IMU samples are averaged
//             in consecutive non-overlapping clusters of tau, and the differences d of consecutive cluster
//             means of all three axes are pooled. White noise of density N gives var(d) = 2 N^2 / tau.
//             The variance is the mean of d^2 (the Allan variance; vibration is heavy-tailed, and its bursts
//             are noise the estimator must expect), without the differences beyond 10 robust standard
//             deviations (median(d^2) / 0.4549, the median of chi-square(1)), so a glitch does not count;
//   apply     where a sensor's measured density is at least min_ratio times the model's (the model is plainly
//             wrong; a sensor that fits its model keeps it exactly), the ratio r = measured / model raises
//             the model: for the sensors in `sensors` the white noise is replaced by the measured one (x r),
//             for the sensors in `bias_walk` the bias random walk is multiplied by r (the datasheet, which
//             underestimates this sensor's fast errors r times, is taken to underestimate its slow ones as
//             much). Gyroscope and accelerometer are judged separately.
// The defaults (the accelerometer's white noise; no bias walk) follow the ablation in
// docs/results/2026-12-estimator.md.
// `bias_walk: gyroscope` lowers the ATE of the whole semi-real V1_01 flight by a fifth but doubles the yaw
// drift on the semi-real gate's 30 s excerpt, so it is a variant, not the default.
// The rest is measured before the estimator starts, as a system calibrates on the ground before it moves: the
// frames before the end of the rest use a density measured over the whole rest. On EuRoC V1_01 that rest
// starts within the first second (the platform shifts once at 0.75 s) and lasts until take-off at 5.3 s.
#pragma once

#include <optional>
#include <vector>

#include "core/camera.h"
#include "core/config.h"
#include "core/types.h"
#include "estimator/estimator_input.h"
#include "estimator/zero_velocity_options.h"

namespace vigil::estimator {

// Which sensors the measurement may re-weigh.
enum class RestNoiseSensors { kNone, kAccelerometer, kGyroscope, kBoth };

inline const config::EnumNames<RestNoiseSensors>& RestNoiseSensorsNames() {
  static const config::EnumNames<RestNoiseSensors> names = {
      {"none", RestNoiseSensors::kNone},
      {"accelerometer", RestNoiseSensors::kAccelerometer},
      {"gyroscope", RestNoiseSensors::kGyroscope},
      {"both", RestNoiseSensors::kBoth}};
  return names;
}

struct RestNoiseOptions {
  RestNoiseSensors sensors = RestNoiseSensors::kAccelerometer;  // white noise := measured
  RestNoiseSensors bias_walk = RestNoiseSensors::kNone;         // bias random walk x measured / model
  double min_rest_s = 2.0;                                      // a shorter rest measures nothing
  double min_ratio = 2.0;  // measured / model density at which the measurement raises the model
  // Chi-square quantile of the image test that finds the rest: far out in the tail, so that one noisy
  // interval in a hundred does not end the rest (a platform that moves fails the test by orders of
  // magnitude).
  double probability = 0.999999;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Enum("sensors", sensors, RestNoiseSensorsNames(),
           "the sensors whose white noise is measured while the platform stands still at the start (image "
           "test of zero-velocity detection) and used where the model's is plainly lower (vigil's rule; "
           "none: the model alone, as VINS-Mono)");
    v.Enum("bias_walk", bias_walk, RestNoiseSensorsNames(),
           "at_rest: the sensors whose bias random walk is multiplied by the measured / model ratio of their "
           "white noise where that ratio reaches min_ratio (none: the model's bias walks)");
    v.Field("min_rest_s", min_rest_s,
            "at_rest: shortest rest that is measured (the first one this long counts) [s]",
            Bounds::Positive());
    v.Field("min_ratio", min_ratio,
            "at_rest: a measured noise density raises the model (sensors, bias_walk) when it is at least "
            "this many times the model's",
            Bounds::AtLeast(1.0));
    v.Field("probability", probability,
            "at_rest: chi-square quantile of the image test that finds the rest (the static start's test: "
            "zero_velocity.static_init_pixel_std_px and min_features set it)",
            Bounds::Closed(0.5, 0.999999));
  }
};

// A rest as [first, last] camera frame times.
struct RestSpan {
  int64_t t0_ns = 0;
  int64_t t1_ns = 0;
};
// The first maximal run of consecutive frames that lasts at least min_rest_s, each frame image-stationary
// against the one before it and against the run's first frame; empty when there is none. `image_test` sets
// the test (its pixel_std_px and probability included); two frames that share fewer than
// image_test.min_features features are not stationary.
std::optional<RestSpan> FindFirstRest(const std::vector<CameraFrame>& frames, const CameraModel& camera,
                                      const ZeroVelocityOptions& image_test, double min_rest_s);

// The white-noise density of one sensor ({gyro, accel} selected by `accel`) over [t0, t1] at averaging time
// tau_s, pooled over the axes; `differences` receives the count. Empty when fewer than 24 differences.
std::optional<double> AllanWhiteNoiseDensity(const ImuStream& imu, int64_t t0_ns, int64_t t1_ns, double tau_s,
                                             bool accel, int* differences);

// The rule on a whole input: measures the rest and raises `model` where it applies. `model` is the noise the
// estimator would use without the rule.
RestNoise MeasureRestNoise(const ImuStream& imu, const std::vector<CameraFrame>& frames,
                           const CameraModel& camera, const ZeroVelocityOptions& zero_velocity,
                           const RestNoiseOptions& options, ImuNoiseDensities* model);

}  // namespace vigil::estimator
