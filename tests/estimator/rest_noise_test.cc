// The IMU noise measured at rest (rest_noise.h): the Allan white-noise density, the rest found by the image
// test, and the rule that raises the model only where it is plainly too low.
#include "estimator/rest_noise.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/random.h"
#include "estimator/zero_velocity_detector.h"

namespace vigil::estimator {
namespace {

constexpr double kImuRateHz = 200.0;
constexpr double kCameraRateHz = 20.0;
constexpr double kGyroDensity = 1.7e-4;   // EuRoC's datasheet values [rad/s/sqrt(Hz)]
constexpr double kAccelDensity = 2.0e-3;  // [m/s^2/sqrt(Hz)]

int64_t SecondsToNs(double t_s) { return static_cast<int64_t>(std::llround(t_s * 1e9)); }

// The noise model at the datasheet's white noise (the bias walks as ImuNoiseDensities has them).
ImuNoiseDensities DatasheetModel() {
  ImuNoiseDensities model;
  model.gyro_noise_density = kGyroDensity;
  model.accel_noise_density = kAccelDensity;
  return model;
}

// A still IMU over [0, duration_s]: biases and gravity, white noise of the given densities, plus a vibration
// of `vibration_mps2` amplitude at 67 Hz on every accelerometer axis.
ImuStream StillImu(uint64_t seed, double duration_s, double gyro_density, double accel_density,
                   double vibration_mps2 = 0.0) {
  Rng rng(seed, "rest_noise_test");
  ImuStream imu;
  const double root_rate = std::sqrt(kImuRateHz);
  for (int k = 0; k <= static_cast<int>(duration_s * kImuRateHz); ++k) {
    const double t_s = k / kImuRateHz;
    ImuSample s;
    s.t_ns = SecondsToNs(t_s);
    s.w_B = Eigen::Vector3d(0.002, -0.01, 0.077) + gyro_density * root_rate * rng.NormalVector3();
    s.a_B = Eigen::Vector3d(0.3, -0.2, 9.8) + accel_density * root_rate * rng.NormalVector3() +
            vibration_mps2 * std::sin(2.0 * M_PI * 67.0 * t_s) * Eigen::Vector3d::Ones();
    imu.push_back(s);
  }
  return imu;
}

// Camera frames at 20 Hz over [0, duration_s] seeing 30 features with `noise_px` of noise. The image shifts
// by 5 px at each time in `jumps_s`, drifts `drift_px` per frame from the start, and moves 3 px per frame
// from `moving_from_s` on.
std::vector<CameraFrame> Frames(uint64_t seed, double duration_s, const std::vector<double>& jumps_s,
                                double moving_from_s, double noise_px = 0.5, double drift_px = 0.0) {
  Rng rng(seed, "rest_noise_test");
  std::vector<Eigen::Vector2d> features;
  for (int id = 0; id < 30; ++id) features.emplace_back(100.0 + 10.0 * id, 80.0 + 7.0 * id);
  std::vector<CameraFrame> frames;
  double shift_px = 0.0;
  for (int k = 0; k <= static_cast<int>(duration_s * kCameraRateHz); ++k) {
    const double t_s = k / kCameraRateHz;
    for (const double jump_s : jumps_s)
      if (std::abs(t_s - jump_s) < 0.5 / kCameraRateHz) shift_px += 5.0;
    if (t_s >= moving_from_s) shift_px += 3.0;
    shift_px += drift_px;
    CameraFrame frame;
    frame.t_ns = SecondsToNs(t_s);
    for (int id = 0; id < 30; ++id)
      frame.features.push_back({id, features[id] + Eigen::Vector2d(shift_px, 0.0) +
                                        noise_px * Eigen::Vector2d(rng.Normal(), rng.Normal())});
    frames.push_back(frame);
  }
  return frames;
}

double Seconds(int64_t t_ns) { return t_ns * 1e-9; }

TEST(RestNoise, AllanDensityOfWhiteNoiseIsItsDensity) {
  const ImuStream imu = StillImu(7, 10.0, kGyroDensity, kAccelDensity);
  int differences = 0;
  const auto gyro = AllanWhiteNoiseDensity(imu, 0, SecondsToNs(10.0), 0.05, false, &differences);
  const auto accel = AllanWhiteNoiseDensity(imu, 0, SecondsToNs(10.0), 0.05, true, &differences);
  ASSERT_TRUE(gyro && accel);
  EXPECT_EQ(differences, 3 * 199);
  // About 600 differences: the variance is known to about 6 %, the density to about 3 %.
  EXPECT_NEAR(*gyro / kGyroDensity, 1.0, 0.1);
  EXPECT_NEAR(*accel / kAccelDensity, 1.0, 0.1);
}

TEST(RestNoise, AGlitchDoesNotCountAsNoise) {
  ImuStream imu = StillImu(8, 10.0, kGyroDensity, kAccelDensity);
  for (const int k : {301, 902, 1503}) imu[k].a_B.z() += 50.0;  // the paper's glitch size
  int differences = 0;
  const auto accel = AllanWhiteNoiseDensity(imu, 0, SecondsToNs(10.0), 0.05, true, &differences);
  ASSERT_TRUE(accel);
  EXPECT_NEAR(*accel / kAccelDensity, 1.0, 0.1);
}

TEST(RestNoise, VibrationRaisesTheMeasuredDensity) {
  // 0.3 m/s^2 at 67 Hz does not average out in 50 ms clusters (3.35 periods).
  const ImuStream imu = StillImu(9, 10.0, kGyroDensity, kAccelDensity, 0.3);
  int differences = 0;
  const auto accel = AllanWhiteNoiseDensity(imu, 0, SecondsToNs(10.0), 0.05, true, &differences);
  ASSERT_TRUE(accel);
  EXPECT_GT(*accel / kAccelDensity, 3.0);
}

TEST(RestNoise, TooShortARestMeasuresNothing) {
  const ImuStream imu = StillImu(10, 0.3, kGyroDensity, kAccelDensity);
  int differences = 0;
  EXPECT_FALSE(AllanWhiteNoiseDensity(imu, 0, SecondsToNs(0.3), 0.05, false, &differences));
  EXPECT_EQ(differences, 3 * 5);
}

TEST(RestNoise, TheFirstRestLongEnoughIsFound) {
  CameraModel camera;
  ZeroVelocityOptions image_test;
  image_test.probability = RestNoiseOptions{}.probability;
  // Still, a shift at 0.75 s, still until the motion starts at 5 s.
  const std::vector<CameraFrame> frames = Frames(11, 8.0, {0.75}, 5.0);
  const auto rest = FindFirstRest(frames, camera, image_test, 2.0);
  ASSERT_TRUE(rest);
  EXPECT_NEAR(Seconds(rest->t0_ns), 0.75, 1e-6);
  EXPECT_NEAR(Seconds(rest->t1_ns), 4.95, 1e-6);
  // The rest before the shift is too short, and none is 5 s long.
  EXPECT_FALSE(FindFirstRest(frames, camera, image_test, 5.0));
  // A platform that moves from the start has no rest.
  EXPECT_FALSE(FindFirstRest(Frames(12, 8.0, {}, 0.0), camera, image_test, 0.1));
}

// A slow motion passes the image test at every interval, but not over the whole span: at 1.5 px, a drift of
// 0.5 px per frame is within the noise of each interval, and 10 px after a second. A rest must hold since its
// first frame too.
TEST(RestNoise, ASlowDriftIsNoRest) {
  CameraModel camera;
  ZeroVelocityOptions image_test;
  image_test.pixel_std_px = 1.5;
  image_test.probability = RestNoiseOptions{}.probability;
  const std::vector<CameraFrame> drifting = Frames(16, 8.0, {}, 5.0, 0.5, 0.5);
  EXPECT_FALSE(FindFirstRest(drifting, camera, image_test, 2.0));
  // Each interval alone is still.
  for (std::size_t k = 1; k < drifting.size(); k += 20) {
    const auto test = ImageStationarity(NormalizedFeatures(drifting[k - 1], camera),
                                        NormalizedFeatures(drifting[k], camera), camera.fx, image_test);
    ASSERT_TRUE(test);
    EXPECT_TRUE(test->passed()) << "interval " << k;
  }
  // Without the drift the same frames stand still until the motion.
  const auto rest = FindFirstRest(Frames(16, 8.0, {}, 5.0), camera, image_test, 2.0);
  ASSERT_TRUE(rest);
  EXPECT_NEAR(Seconds(rest->t0_ns), 0.0, 1e-6);
}

// The rest is measured with the static start's image test (static_init_pixel_std_px, 1.5 px by default):
// on tracks of 1 px noise the zero-velocity test of 0.5 px finds no rest, and the model kept the datasheet's
// noise, while the static start found the stand and stood on it.
TEST(RestNoise, TheRestIsFoundAtTheStaticStartsTrackNoise) {
  CameraModel camera;
  const std::vector<CameraFrame> frames = Frames(17, 8.0, {}, 5.0, 1.0);
  const ImuStream noisy = StillImu(18, 8.0, 5 * kGyroDensity, 5 * kAccelDensity);
  ZeroVelocityOptions zero_velocity;
  ASSERT_EQ(zero_velocity.pixel_std_px, 0.5);
  ASSERT_EQ(zero_velocity.static_init_pixel_std_px, 1.5);
  ImuNoiseDensities model = DatasheetModel();
  const RestNoise found = MeasureRestNoise(noisy, frames, camera, zero_velocity, RestNoiseOptions{}, &model);
  EXPECT_GT(found.rest_s, 4.5);
  EXPECT_TRUE(found.accel_applied);
  ZeroVelocityOptions at_half_a_pixel = zero_velocity;
  at_half_a_pixel.static_init_pixel_std_px = 0.5;
  ImuNoiseDensities kept = DatasheetModel();
  EXPECT_EQ(MeasureRestNoise(noisy, frames, camera, at_half_a_pixel, RestNoiseOptions{}, &kept).rest_s, 0.0);
  EXPECT_EQ(kept.accel_noise_density, kAccelDensity);
}

// The static start's image test at the frames' track noise.
ZeroVelocityOptions TestAtHalfAPixel() {
  ZeroVelocityOptions options;
  options.static_init_pixel_std_px = 0.5;
  return options;
}

TEST(RestNoise, OnlyAModelPlainlyTooLowIsRaised) {
  CameraModel camera;
  const std::vector<CameraFrame> frames = Frames(13, 8.0, {}, 5.0);
  const ImuNoiseDensities model = DatasheetModel();
  RestNoiseOptions options;
  options.sensors = RestNoiseSensors::kBoth;

  // A sensor that fits its model keeps the model exactly.
  ImuNoiseDensities fits = model;
  const RestNoise fit = MeasureRestNoise(StillImu(14, 8.0, kGyroDensity, kAccelDensity), frames, camera,
                                         TestAtHalfAPixel(), options, &fits);
  EXPECT_NEAR(fit.rest_s, 4.95, 1e-6);
  EXPECT_NEAR(fit.tau_s, 0.05, 1e-9);
  ASSERT_TRUE(fit.gyro_noise_density && fit.accel_noise_density);
  EXPECT_FALSE(fit.gyro_applied || fit.accel_applied);
  EXPECT_EQ(fits.gyro_noise_density, kGyroDensity);
  EXPECT_EQ(fits.accel_noise_density, kAccelDensity);

  // Five times the model's white noise on both sensors: each is raised to what was measured ...
  const ImuStream noisy = StillImu(15, 8.0, 5 * kGyroDensity, 5 * kAccelDensity);
  ImuNoiseDensities raised = model;
  const RestNoise both = MeasureRestNoise(noisy, frames, camera, TestAtHalfAPixel(), options, &raised);
  EXPECT_TRUE(both.gyro_applied && both.accel_applied);
  EXPECT_EQ(raised.gyro_noise_density, *both.gyro_noise_density);
  EXPECT_NEAR(raised.accel_noise_density / kAccelDensity, 5.0, 0.5);
  EXPECT_EQ(raised.accel_bias_random_walk, model.accel_bias_random_walk);

  // ... unless the options leave a sensor out ...
  options.sensors = RestNoiseSensors::kAccelerometer;
  ImuNoiseDensities accel_only = model;
  const RestNoise accel = MeasureRestNoise(noisy, frames, camera, TestAtHalfAPixel(), options, &accel_only);
  EXPECT_TRUE(accel.accel_applied);
  EXPECT_FALSE(accel.gyro_applied);
  EXPECT_EQ(accel_only.gyro_noise_density, kGyroDensity);

  // ... or the rule is off.
  options.sensors = RestNoiseSensors::kNone;
  ImuNoiseDensities off = model;
  const RestNoise none = MeasureRestNoise(noisy, frames, camera, TestAtHalfAPixel(), options, &off);
  EXPECT_EQ(none.rest_s, 0.0);
  EXPECT_EQ(off.accel_noise_density, kAccelDensity);
}

TEST(RestNoise, BiasWalkIsScaledByTheMeasuredRatio) {
  CameraModel camera;
  const std::vector<CameraFrame> frames = Frames(13, 8.0, {}, 5.0);
  const ImuNoiseDensities model = DatasheetModel();
  const ImuStream noisy = StillImu(15, 8.0, 5 * kGyroDensity, 5 * kAccelDensity);
  RestNoiseOptions options;
  options.sensors = RestNoiseSensors::kNone;
  options.bias_walk = RestNoiseSensors::kGyroscope;

  // The gyroscope's bias walk grows by the measured ratio (about 5); its white noise and the accelerometer
  // keep the model.
  ImuNoiseDensities walk = model;
  const RestNoise gyro = MeasureRestNoise(noisy, frames, camera, TestAtHalfAPixel(), options, &walk);
  ASSERT_TRUE(gyro.gyro_noise_density);
  EXPECT_TRUE(gyro.gyro_bias_walk_applied);
  EXPECT_FALSE(gyro.gyro_applied || gyro.accel_applied || gyro.accel_bias_walk_applied);
  EXPECT_DOUBLE_EQ(walk.gyro_bias_random_walk / model.gyro_bias_random_walk,
                   *gyro.gyro_noise_density / kGyroDensity);
  EXPECT_NEAR(walk.gyro_bias_random_walk / model.gyro_bias_random_walk, 5.0, 0.5);
  EXPECT_EQ(walk.gyro_noise_density, kGyroDensity);
  EXPECT_EQ(walk.accel_bias_random_walk, model.accel_bias_random_walk);
  EXPECT_EQ(walk.accel_noise_density, kAccelDensity);

  // With white noise and bias walk both chosen for both sensors, each sensor gets both.
  options.sensors = options.bias_walk = RestNoiseSensors::kBoth;
  ImuNoiseDensities all = model;
  const RestNoise both = MeasureRestNoise(noisy, frames, camera, TestAtHalfAPixel(), options, &all);
  ASSERT_TRUE(both.accel_noise_density);
  EXPECT_TRUE(both.gyro_applied && both.accel_applied && both.gyro_bias_walk_applied &&
              both.accel_bias_walk_applied);
  EXPECT_NEAR(all.accel_bias_random_walk / model.accel_bias_random_walk, 5.0, 0.5);
  EXPECT_EQ(all.accel_noise_density, *both.accel_noise_density);
  EXPECT_DOUBLE_EQ(all.accel_bias_random_walk / model.accel_bias_random_walk,
                   *both.accel_noise_density / kAccelDensity);

  // A sensor that fits its model keeps its bias walk.
  ImuNoiseDensities fits = model;
  const RestNoise fit = MeasureRestNoise(StillImu(14, 8.0, kGyroDensity, kAccelDensity), frames, camera,
                                         TestAtHalfAPixel(), options, &fits);
  EXPECT_FALSE(fit.gyro_bias_walk_applied || fit.accel_bias_walk_applied);
  EXPECT_EQ(fits.gyro_bias_random_walk, model.gyro_bias_random_walk);
}

}  // namespace
}  // namespace vigil::estimator
