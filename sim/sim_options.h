// Options of the simulator: trajectory, landmarks, IMU, camera and glitch injection.
// Keys are documented in configs/README.md (generated from these Visit() descriptions).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/config.h"
#include "core/types.h"
#include "sim/fault_options.h"
#include "sim/image_options.h"

namespace vigil::sim {

enum class TrajectoryType { kEllipse, kRescue, kWaypoints, kRecording };

// How a recorded trajectory is fitted (sim/recorded_trajectory.h): a cumulative cubic B-spline on
// SO(3) x R^3 with uniform knots, fitted to the recorded poses by least squares.
struct RecordedTrajectoryOptions {
  double knot_spacing_s = 0.0;  // 0: the recording's median pose spacing
  double smoothing = 0.05;      // weight of the control points' second differences (dimensionless)

  template <class V>
  void Visit(V& v) {
    v.Field("knot_spacing_s", knot_spacing_s,
            "knot spacing of the spline fitted to a recording [s] (0: the recording's median pose spacing)",
            config::Bounds::NonNegative());
    v.Field("smoothing", smoothing,
            "weight of the spline's second differences against the pose residuals (0: none; larger: "
            "smoother, farther from the poses)",
            config::Bounds::NonNegative());
  }
};

struct TrajectoryOptions {
  TrajectoryType type = TrajectoryType::kEllipse;
  std::string waypoints_file;  // for type waypoints: timed poses (see configs/README.md)
  std::string recording;       // for type recording: a ground-truth file or EuRoC folder
  RecordedTrajectoryOptions spline;

  template <class V>
  void Visit(V& v) {
    v.Enum(
        "type", type,
        config::EnumNames<TrajectoryType>{{"ellipse", TrajectoryType::kEllipse},
                                          {"rescue", TrajectoryType::kRescue},
                                          {"waypoints", TrajectoryType::kWaypoints},
                                          {"recording", TrajectoryType::kRecording}},
        "motion model: ellipse (vio_data_simulation reference), rescue (ground robot over ramps and steps), "
        "waypoints (C2 spline through timed poses), recording (B-spline fitted to a recorded ground truth)");
    v.Field("waypoints_file", waypoints_file,
            "timed pose CSV for type waypoints (relative to the config file, or $VIGIL_DATA/...; see "
            "configs/README.md)");
    v.Field("recording", recording,
            "ground truth for type recording: EuRoC state_groundtruth_estimate0/data.csv (or its mav0 folder "
            "or the folder holding mav0) or a TUM / rpg text file (relative to the config file, or "
            "$VIGIL_DATA/...; see docs/recordings-trajectory.md)");
    v.Section("spline", spline, "the spline fitted to a recording (type recording)");
  }
};

enum class LandmarkLayout { kHouse, kRandom, kHouseAndRandom };

// Most random landmarks a scene holds: 100,000 (the shipped configs use 300). Each frame projects every
// landmark, so the count is bounded when the config is read (2e9 made the allocation fail).
inline constexpr int kMaxRandomLandmarks = 100000;

struct LandmarkOptions {
  LandmarkLayout layout = LandmarkLayout::kHouse;
  int random_count = 0;          // random points on the walls of a room around the path
  double random_margin_m = 5.0;  // distance of the walls from the path's horizontal bounding box
  double random_height_m = 4.0;  // extra wall height, split above and below the path's height range

  template <class V>
  void Visit(V& v) {
    v.Enum(
        "layout", layout,
        config::EnumNames<LandmarkLayout>{{"house", LandmarkLayout::kHouse},
                                          {"random", LandmarkLayout::kRandom},
                                          {"house+random", LandmarkLayout::kHouseAndRandom}},
        "house: the 36-point house of the reference simulator; random: points on the walls of a room around "
        "the path");
    v.Field("random_count", random_count, "number of random landmarks (layouts random and house+random)",
            config::Bounds::Closed(0, kMaxRandomLandmarks));
    v.Field("random_margin_m", random_margin_m,
            "distance of the random landmarks' walls from the path's horizontal bounding box [m]",
            config::Bounds::Positive());
    v.Field("random_height_m", random_height_m,
            "random landmarks span the path's height range extended by half this above and below [m]",
            config::Bounds::NonNegative());
  }
};

struct ImuNoiseOptions {
  bool enabled = true;
  double gyro_noise_density = 0.015;                         // [rad/s/sqrt(Hz)]
  double accel_noise_density = 0.019;                        // [m/s^2/sqrt(Hz)]
  double gyro_bias_random_walk = 1e-5;                       // [rad/s^2/sqrt(Hz)]
  double accel_bias_random_walk = 1e-4;                      // [m/s^3/sqrt(Hz)]
  std::vector<double> initial_gyro_bias = {0.0, 0.0, 0.0};   // b_g at t = 0 [rad/s]
  std::vector<double> initial_accel_bias = {0.0, 0.0, 0.0};  // b_a at t = 0 [m/s^2]
  double switch_on_gyro_bias_std = 0.0;                      // per axis, drawn once [rad/s]
  double switch_on_accel_bias_std = 0.0;                     // per axis, drawn once [m/s^2]

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("enabled", enabled,
            "add white noise, initial biases and bias random walk (false: ideal IMU, zero bias)");
    // Every key that feeds the IMU is bounded far beyond any sensor (a consumer part is near 0.01), and so
    // that the samples stay values a dataset may hold (|IMU values| <= 1e6, docs/formats.md).
    v.Field("gyro_noise_density", gyro_noise_density, "gyro white noise density [rad/s/sqrt(Hz)]",
            Bounds::Closed(0.0, 10.0));
    v.Field("accel_noise_density", accel_noise_density, "accelerometer white noise density [m/s^2/sqrt(Hz)]",
            Bounds::Closed(0.0, 100.0));
    v.Field("gyro_bias_random_walk", gyro_bias_random_walk, "gyro bias random walk [rad/s^2/sqrt(Hz)]",
            Bounds::Closed(0.0, 1.0));
    v.Field("accel_bias_random_walk", accel_bias_random_walk,
            "accelerometer bias random walk [m/s^3/sqrt(Hz)]", Bounds::Closed(0.0, 10.0));
    v.Field("initial_gyro_bias", initial_gyro_bias, "gyro bias b_g at t = 0 (3 numbers: x, y, z) [rad/s]",
            Bounds::Closed(-100.0, 100.0));
    v.Field("initial_accel_bias", initial_accel_bias,
            "accelerometer bias b_a at t = 0 (3 numbers: x, y, z) [m/s^2]", Bounds::Closed(-1000.0, 1000.0));
    v.Field("switch_on_gyro_bias_std", switch_on_gyro_bias_std,
            "spread of the gyro bias at switch-on: N(0, std^2) per axis, drawn once per run and added to "
            "initial_gyro_bias [rad/s]",
            Bounds::Closed(0.0, 10.0));
    v.Field(
        "switch_on_accel_bias_std", switch_on_accel_bias_std,
        "spread of the accelerometer bias at switch-on: N(0, std^2) per axis, drawn once per run and added "
        "to initial_accel_bias [m/s^2]",
        Bounds::Closed(0.0, 100.0));
  }
};

enum class ImuSource { kSimulated, kRecording };

// Vibration of the platform (rotors, a track, an engine) as the IMU senses it: band-limited, zero-mean, on
// every axis (sim/vibration.h). Off while frequency_hz is 0 or both amplitudes are 0.
struct ImuVibrationOptions {
  double frequency_hz = 0.0;    // centre of the band (rotor or track frequency)
  double bandwidth_hz = 10.0;   // width of the band around frequency_hz
  double accel_rms_mps2 = 0.0;  // per accelerometer axis
  double gyro_rms_radps = 0.0;  // per gyro axis
  int components = 16;          // sinusoids per axis

  bool enabled() const { return frequency_hz > 0.0 && (accel_rms_mps2 > 0.0 || gyro_rms_radps > 0.0); }

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field(
        "frequency_hz", frequency_hz,
        "centre frequency of the vibration (a rotor or track frequency; above half imu.rate_hz it aliases "
        "as in a real sampled sensor) [Hz] (0: no vibration)",
        Bounds::Closed(0.0, 1e6));
    v.Field("bandwidth_hz", bandwidth_hz, "width of the vibration band around frequency_hz [Hz]",
            Bounds::Closed(0.0, 1e6));
    v.Field("accel_rms_mps2", accel_rms_mps2, "vibration rms on each accelerometer axis [m/s^2]",
            Bounds::Closed(0.0, 1000.0));
    v.Field("gyro_rms_radps", gyro_rms_radps, "vibration rms on each gyro axis [rad/s]",
            Bounds::Closed(0.0, 100.0));
    v.Field("components", components,
            "sinusoids per axis, each with a random frequency in the band and a random phase",
            Bounds::Closed(1, 1000));
  }
};

// Sensor classes whose datasheet figures replace the noise model (sim/imu_presets.h).
enum class ImuPreset { kNone, kAdis16448, kBmi088, kMpu6050 };

struct ImuOptions {
  ImuSource source = ImuSource::kSimulated;
  std::string recording;           // for source recording: a EuRoC folder (sim/semi_real.h)
  double recording_start_s = 0.0;  // semi-real window start, from the recording's first ground-truth row
  double rate_hz = 200.0;
  ImuPreset preset = ImuPreset::kNone;
  ImuNoiseOptions noise;
  ImuVibrationOptions vibration;

  template <class V>
  void Visit(V& v) {
    v.Enum("source", source,
           config::EnumNames<ImuSource>{{"simulated", ImuSource::kSimulated},
                                        {"recording", ImuSource::kRecording}},
           "simulated: synthesized along trajectory.*; recording: the recorded IMU of imu.recording, with "
           "camera tracks synthesized along its ground truth (a semi-real dataset, docs/recordings.md)");
    v.Field("recording", recording,
            "recording for source recording: a EuRoC folder (holding mav0/, or mav0/ itself) or a vigil "
            "dataset, with ground truth and a camera (relative to the config file, or $VIGIL_DATA/...: "
            "inside the folder the environment variable VIGIL_DATA names, docs/datasets.md)");
    v.Field("recording_start_s", recording_start_s,
            "source recording: start of the semi-real window after the first ground-truth row [s]; the "
            "window lasts duration_s",
            config::Bounds::NonNegative());
    v.Field("rate_hz", rate_hz, "IMU sampling rate [Hz]", config::Bounds{0.0, 1e5, true, false});
    v.Enum("preset", preset,
           config::EnumNames<ImuPreset>{{"none", ImuPreset::kNone},
                                        {"adis16448", ImuPreset::kAdis16448},
                                        {"bmi088", ImuPreset::kBmi088},
                                        {"mpu6050", ImuPreset::kMpu6050}},
           "sensor class whose figures become the defaults of imu.noise.* (keys written in the config still "
           "win; docs/imu-models.md); none: vigil's own defaults");
    v.Section("noise", noise, "IMU noise model");
    v.Section("vibration", vibration, "platform vibration sensed by the IMU (docs/imu-models.md)");
  }
};

struct GlitchOptions {
  bool enabled = false;
  double mean = 0.0;   // mu of N(mu, sigma), in the axis' unit
  double std = 1.0;    // sigma (a standard deviation)
  double rate = 0.01;  // probability per IMU sample that a glitch (burst) starts
  std::vector<ImuAxis> axes = {ImuAxis::kAz};
  int burst_length = 1;  // consecutive samples per glitch

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("enabled", enabled, "inject glitches into the measured IMU stream");
    // Bounded so that every glitched sample stays a value a dataset may hold (|IMU values| <= 1e6).
    v.Field("mean", mean, "mean mu of the N(mu, sigma) glitch offset [rad/s or m/s^2]",
            Bounds::Closed(-1e4, 1e4));
    v.Field("std", std, "standard deviation sigma of the glitch offset", Bounds::Closed(0.0, 1e4));
    v.Field("rate", rate, "probability per IMU sample that a glitch starts", Bounds::Probability());
    v.EnumList("axes", axes,
               config::EnumNames<ImuAxis>{{"wx", ImuAxis::kWx},
                                          {"wy", ImuAxis::kWy},
                                          {"wz", ImuAxis::kWz},
                                          {"ax", ImuAxis::kAx},
                                          {"ay", ImuAxis::kAy},
                                          {"az", ImuAxis::kAz}},
               "IMU axes that receive glitches (an independent draw per axis)");
    v.Field("burst_length", burst_length, "consecutive samples affected by one glitch", Bounds::AtLeast(1));
  }
};

// Everything the simulator needs. Its sections sit at the top level of a run config.
struct SimOptions {
  double duration_s = 20.0;
  double gravity_mps2 = 9.81;
  TrajectoryOptions trajectory;
  LandmarkOptions landmarks;
  ImuOptions imu;
  CameraModel camera;
  GlitchOptions glitch;
  FaultOptions faults;
  ImageOptions images;

  template <class V>
  void Visit(V& v) {
    // 0 or from 0.5 s (ValidateSimOptions): a shorter recording has too few samples and frames for a run.
    v.Field("duration_s", duration_s,
            "simulated duration [s], 0 or from 0.5; 0: to the end of the trajectory (types waypoints and "
            "recording)",
            config::Bounds::Closed(0.0, 1e6));
    v.Field("gravity_mps2", gravity_mps2, "magnitude g of gravity g_W = (0, 0, -g) [m/s^2]",
            config::Bounds{0.0, 100.0, true, false});
    v.Section("trajectory", trajectory, "body motion");
    v.Section("landmarks", landmarks, "3-D landmarks");
    v.Section("imu", imu, "IMU sampling and noise");
    v.Section("camera", camera, "pinhole camera and feature tracks");
    v.Section("glitch", glitch, "injected IMU glitches");
    v.Section("faults", faults,
              "low-cost IMU faults besides the glitches (sim/imu_faults.h gives their order)");
    v.Section("images", images, "rendered camera images (vigil simulate --images; sim/image_renderer.h)");
  }
};

// Makes a relative trajectory.waypoints_file, trajectory.recording or imu.recording absolute, relative to
// `base_dir` (the config file's directory for paths read from a file, the working directory for --set
// values), so a written config.yaml works from anywhere. "$VIGIL_DATA/..." becomes a path in the folder the
// environment variable names (core/data_dir.h; left as it is while VIGIL_DATA is unset, which
// ValidateSimOptions refuses). Empty and absolute paths are left alone.
void ResolveRelativePaths(const std::filesystem::path& base_dir, SimOptions* options);

// duration_s: 0 means "to the end of the trajectory": replaces it by the span of the waypoints or the
// recording (reading only their timestamps). Other values, and trajectories without an end, are left alone
// (ValidateSimOptions then refuses 0). Throws InputError "trajectory.<key>: file:line: reason", or
// "duration_s: reason" when that span is shorter than kMinDuration_s.
void ResolveDurationToEnd(SimOptions* options);

// Longest recording the simulator accepts (it is held in memory): 1e7 IMU samples, 14 h at 200 Hz.
inline constexpr double kMaxImuSamples = 1e7;

// Shortest duration_s: shorter recordings have too few samples and frames for a run to read them.
inline constexpr double kMinDuration_s = 0.5;

// Cross-field checks that single keys' bounds cannot express; throws InputError("<origin>: key: reason").
void ValidateSimOptions(const SimOptions& options, const std::string& origin);

}  // namespace vigil::sim
