// The seam between the sliding window and its initialization.
//
// The window collects frames (normalized feature observations + IMU preintegrated from the previous frame)
// until an Initializer turns the whole window into metric states in W (gravity along -z). Two
// implementations: GroundTruthInitializer (ground_truth_initializer.h) and VinsInitializer (init/,
// visual-inertial alignment). MakeInitializer (make_initializer.h) picks one from the options.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/types.h"
#include "estimator/preintegration.h"

namespace vigil::estimator {

struct InitFrame {
  int64_t t_ns = 0;
  std::map<int, Eigen::Vector2d> features_n;    // track id -> normalized image point (x/z, y/z) in C
  std::optional<Preintegration> imu_from_prev;  // IMU from the previous window frame (none for the first)
};

struct InitResult {
  std::vector<NavState> states;                // one per window frame, in W (gravity along -z), metric
  std::map<int, Eigen::Vector3d> landmarks_W;  // optional triangulated points (depth initialization)
  std::string failure_reason;                  // set when TryInitialize returns false
  bool stationary = false;                     // a static start: hold the window still until it moves
};

class Initializer {
 public:
  virtual ~Initializer() = default;
  // Called with the full window (oldest first) until it returns true.
  virtual bool TryInitialize(const std::vector<InitFrame>& window, InitResult* result) = 0;
  // Whether the estimator may reset and call TryInitialize again after a failure (groundtruth: false).
  virtual bool CanReinitialize() const = 0;
};

}  // namespace vigil::estimator
