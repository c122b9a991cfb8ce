// The recording vigil writes for an external estimator (docs/external-estimators.md), read as this adapter
// needs it: the IMU stream and its noise (mav0/imu0/), the camera (mav0/cam0/sensor.yaml), the feature tracks
// (features.csv beside mav0/: undistorted pinhole pixels) and, when present, the ground truth
// (mav0/state_groundtruth_estimate0/data.csv). Times stay integer nanoseconds as written.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace vigil_openvins {

// Bad input: the message names the file (and line) and the adapter exits with status 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ImuSample {
  int64_t t_ns = 0;
  Eigen::Vector3d w_B;  // [rad/s]
  Eigen::Vector3d a_B;  // [m/s^2]
};

// imu0/sensor.yaml: continuous-time densities, as Kalibr and OpenVINS take them.
struct ImuNoise {
  double rate_hz = 0.0;
  double gyro_noise_density = 0.0;                     // [rad / s / sqrt(Hz)]
  double gyro_random_walk = 0.0;                       // [rad / s^2 / sqrt(Hz)]
  double accel_noise_density = 0.0;                    // [m / s^2 / sqrt(Hz)]
  double accel_random_walk = 0.0;                      // [m / s^3 / sqrt(Hz)]
  Eigen::Matrix4d T_BI = Eigen::Matrix4d::Identity();  // imu0's T_BS: IMU -> body
};

// cam0/sensor.yaml (pinhole, radial-tangential).
struct Camera {
  int width = 0, height = 0;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  std::vector<double> distortion;  // k1, k2, p1, p2 (of the images; tracks are undistorted)
  Eigen::Matrix4d T_BC = Eigen::Matrix4d::Identity();  // cam0's T_BS: camera -> body
};

// One camera frame's feature tracks: (id, undistorted pixel).
struct FrameTracks {
  int64_t t_ns = 0;
  std::vector<std::pair<size_t, Eigen::Vector2d>> uv;
};

// One ground-truth row: body pose and velocity in the world, the biases in effect.
struct GroundTruth {
  int64_t t_ns = 0;
  Eigen::Vector3d p_WB;
  Eigen::Quaterniond q_WB;
  Eigen::Vector3d v_WB;
  Eigen::Vector3d b_gyro, b_accel;
};

struct Recording {
  std::vector<ImuSample> imu;
  ImuNoise noise;
  Camera camera;
  std::vector<int64_t> frame_times_ns;   // cam0/data.csv
  std::vector<FrameTracks> tracks;       // features.csv, one entry per frame with tracks, in time order
  std::vector<GroundTruth> groundtruth;  // empty when the recording has none
};

// Reads DIR (the folder holding mav0/ and features.csv). Throws InputError.
Recording ReadRecording(const std::filesystem::path& dir);

}  // namespace vigil_openvins
