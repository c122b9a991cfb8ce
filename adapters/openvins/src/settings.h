// What the adapter asks of OpenVINS, and the OpenVINS configuration folder written from it and from the
// recording: estimator_config.yaml (the estimator's settings), kalibr_imu_chain.yaml (imu0/sensor.yaml's
// noise) and kalibr_imucam_chain.yaml (cam0/sensor.yaml's camera). OpenVINS reads the folder through its own
// parser.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "recording.h"

namespace vigil_openvins {

// OpenVINS keeps feature ids up to 4 x num_aruco for ArUco tags (updated as such); vigil's track ids are
// shifted past them.
inline constexpr int kArucoTags = 1024;
inline size_t OpenvinsFeatureId(size_t vigil_id) { return vigil_id + 4 * kArucoTags + 1; }

enum class InitMode {
  kOpenvins,     // OpenVINS's own initializer (dynamic: the platform may move from the start)
  kGroundtruth,  // the state at the first camera frame taken from the recording's ground truth
};

struct Settings {
  InitMode init = InitMode::kOpenvins;
  double gravity_mps2 = 9.81;   // magnitude of gravity
  double pixel_sigma_px = 1.0;  // std of a feature's pixel in the MSCKF and SLAM updates
  int max_clones = 11;          // sliding window of cloned poses
  int max_slam = 50;            // features kept in the state
  double init_window_s = 2.0;   // IMU and tracks the initializer looks at
  // Features the dynamic initializer uses at most; it gives up while fewer than 3/4 of this many are tracked
  // over its window, so OpenVINS's usual 50 never starts on paper.yaml's 36-point house.
  int init_max_features = 30;
  std::string verbosity = "WARNING";  // OpenVINS's print level: ALL, DEBUG, INFO, WARNING, ERROR, SILENT
};

// Writes the three files into `dir` (created) and returns the estimator_config.yaml path.
std::filesystem::path WriteOpenvinsConfig(const std::filesystem::path& dir, const Settings& settings,
                                          const Recording& recording);

}  // namespace vigil_openvins
