// Options of zero-velocity detection and update (estimator.zero_velocity; docs/estimator.md,
// "Zero-velocity").
//
// A window interval (two consecutive window frames) is stationary when every enabled test passes and at least
// one test is enabled (zero_velocity_detector.h):
//   image  the features seen in both frames moved no more than their pixel noise explains: the sum over
//          them of |displacement|^2 / (2 pixel_std_px^2) is below the chi-square quantile `probability` with
//          2 x features degrees of freedom (at least min_features of them);
//   imu    the accelerometer and gyro samples of the interval scatter about their means no more than the
//          noise model's white noise (times imu_noise_multiplier) explains: chi-square on 6 (N - 1) degrees
//          of freedom at the same quantile.
// The image test is on by default and the IMU test off: on EuRoC V1_01 the rotors spin during the whole
// stationary start, and the sample scatter is 8 to 800 times the datasheet's white noise (chi-square per
// degree of freedom, 10-sample windows, 0.5-5.3 s), so an IMU test against the noise model never sees that
// platform still.
#pragma once

#include "core/config.h"

namespace vigil::estimator {

struct ZeroVelocityOptions {
  bool update = false;        // zero-velocity factors on stationary intervals of the tracking window
  bool static_init = true;    // initialize a stationary window from its IMU and hold it still until it moves
  double probability = 0.99;  // chi-square quantile of both tests
  double pixel_std_px = 0.5;  // image test: the track noise per axis (0: image test off) [px]
  // The static start's image test (the initialization window, and the hold after it): the track noise per
  // axis (0: image test off) [px]. As the estimator's reprojection noise (features.pixel_std_px), so that a
  // still start is found on tracks noisier than pixel_std_px: on the semi-real V1_01 flight at 1.0 and 1.5
  // px, 0.5 px missed the 5.3 s stand, and the moving initializer started from a window half still, then ran
  // away (docs/results/2026-12-estimator-speed.md, "Tenth round").
  double static_init_pixel_std_px = 1.5;
  int min_features = 10;              // image test: fewest features seen in both frames
  double imu_noise_multiplier = 0.0;  // imu test: white-noise std scale (0: imu test off)
  // The update: an interval stands still only while the estimate has both its frames slower than this
  // (the newest as the IMU predicts it, the frames of a new window as the initializer gives them). The image
  // test alone cannot tell rest from a slow motion, nor from a camera that looks along its motion at far
  // features: the rescue course's backward camera passed it at 0.7 m/s, and two zero-velocity factors
  // there sent the run 5 m off. Ten times velocity_std_mps.
  double max_speed_mps = 0.1;
  double velocity_std_mps = 0.01;  // the update: std of each velocity about zero [m/s]
  double position_std_m = 1e-3;    // the update: std of the position change between the two frames [m]
  double rotation_std_rad = 1e-3;  // the update: std of the rotation between the two frames [rad]

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("update", update,
            "add zero-velocity factors (both velocities zero, no motion between the frames) on every "
            "stationary interval of the window");
    v.Field("static_init", static_init,
            "when the whole initialization window is stationary, initialize it from the IMU (gravity "
            "direction and gyro bias from the means, velocity zero) and hold it with zero-velocity factors "
            "until it moves; otherwise the configured initializer runs");
    v.Field("probability", probability, "chi-square quantile of the stationarity tests",
            Bounds::Closed(0.5, 0.999999));
    v.Field("pixel_std_px", pixel_std_px,
            "image test: feature track noise std per axis; stationary when the displacements of the shared "
            "features are within it (0: image test off) [px]",
            Bounds::NonNegative());
    v.Field("static_init_pixel_std_px", static_init_pixel_std_px,
            "static start: the image test's track noise std per axis, for the initialization window and "
            "the hold after it (0: image test off) [px]",
            Bounds::NonNegative());
    v.Field("min_features", min_features, "image test: fewest features seen in both frames of an interval",
            Bounds::AtLeast(1));
    v.Field("imu_noise_multiplier", imu_noise_multiplier,
            "imu test: stationary when the samples scatter within this multiple of the white noise std of "
            "the noise model (0: imu test off)",
            Bounds::NonNegative());
    v.Field("max_speed_mps", max_speed_mps,
            "update: an interval counts as stationary only while the estimated speed of both its frames is "
            "at most this (the image test cannot tell rest from a slow motion) [m/s]",
            Bounds::Positive());
    v.Field("velocity_std_mps", velocity_std_mps,
            "zero-velocity factor: std of each frame's velocity about zero [m/s]", Bounds::Positive());
    v.Field("position_std_m", position_std_m,
            "zero-velocity factor: std of the position change between the two frames of a stationary "
            "interval, whatever its length (a still platform does not wander) [m]",
            Bounds::Positive());
    v.Field("rotation_std_rad", rotation_std_rad,
            "zero-velocity factor: std of the rotation between the two frames of a stationary interval "
            "[rad]",
            Bounds::Positive());
  }
};

// The tests of the static start (the initialization window, and the hold after it): the image test with
// static_init_pixel_std_px.
inline ZeroVelocityOptions StaticStartTests(const ZeroVelocityOptions& options) {
  ZeroVelocityOptions still = options;
  still.pixel_std_px = options.static_init_pixel_std_px;
  return still;
}

}  // namespace vigil::estimator
