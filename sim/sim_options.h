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

enum class TrajectoryType { kEllipse, kRescue, kWaypoints };

struct TrajectoryOptions {
  TrajectoryType type = TrajectoryType::kEllipse;
  std::string waypoints_file;  // for type waypoints: timed poses (see configs/README.md)

  template <class V>
  void Visit(V& v) {
    v.Enum(
        "type", type,
        config::EnumNames<TrajectoryType>{{"ellipse", TrajectoryType::kEllipse},
                                          {"rescue", TrajectoryType::kRescue},
                                          {"waypoints", TrajectoryType::kWaypoints}},
        "motion model: ellipse (vio_data_simulation reference), rescue (ground robot over ramps and steps), "
        "waypoints (C2 spline through timed poses)");
    v.Field("waypoints_file", waypoints_file,
            "timed pose CSV for type waypoints (relative to the config file; see configs/README.md)");
  }
};

enum class LandmarkLayout { kHouse, kRandom, kHouseAndRandom };

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
            config::Bounds::NonNegative());
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

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("enabled", enabled,
            "add white noise, initial biases and bias random walk (false: ideal IMU, zero bias)");
    v.Field("gyro_noise_density", gyro_noise_density, "gyro white noise density [rad/s/sqrt(Hz)]",
            Bounds::NonNegative());
    v.Field("accel_noise_density", accel_noise_density, "accelerometer white noise density [m/s^2/sqrt(Hz)]",
            Bounds::NonNegative());
    v.Field("gyro_bias_random_walk", gyro_bias_random_walk, "gyro bias random walk [rad/s^2/sqrt(Hz)]",
            Bounds::NonNegative());
    v.Field("accel_bias_random_walk", accel_bias_random_walk,
            "accelerometer bias random walk [m/s^3/sqrt(Hz)]", Bounds::NonNegative());
    v.Field("initial_gyro_bias", initial_gyro_bias, "gyro bias b_g at t = 0 (3 numbers: x, y, z) [rad/s]");
    v.Field("initial_accel_bias", initial_accel_bias,
            "accelerometer bias b_a at t = 0 (3 numbers: x, y, z) [m/s^2]");
  }
};

struct ImuOptions {
  double rate_hz = 200.0;
  ImuNoiseOptions noise;

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz, "IMU sampling rate [Hz]", config::Bounds::Positive());
    v.Section("noise", noise, "IMU noise model");
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
    // From 0.5 s: a shorter recording has too few samples and frames for a run to read it.
    v.Field("duration_s", duration_s, "simulated duration [s]", config::Bounds::Closed(0.5, 1e6));
    v.Field("gravity_mps2", gravity_mps2, "magnitude g of gravity g_W = (0, 0, -g) [m/s^2]",
            config::Bounds::Positive());
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

// Makes a relative trajectory.waypoints_file absolute, relative to `base_dir` (the config file's directory
// for paths read from a file, the working directory for --set values), so a written config.yaml works from
// anywhere. Empty and absolute paths are left alone.
void ResolveRelativePaths(const std::filesystem::path& base_dir, SimOptions* options);

// Longest recording the simulator accepts (it is held in memory): 1e7 IMU samples, 14 h at 200 Hz.
inline constexpr double kMaxImuSamples = 1e7;

// Cross-field checks that single keys' bounds cannot express; throws InputError("<origin>: key: reason").
void ValidateSimOptions(const SimOptions& options, const std::string& origin);

}  // namespace vigil::sim
