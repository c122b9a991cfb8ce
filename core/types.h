// Shared value types that flow between vigil's stages (sim -> detectors -> estimator -> experiments).
//
// Frame conventions (see docs/formats.md):
//   W  world frame, z up, gravity g_W = (0, 0, -g).
//   B  body frame = IMU frame.
//   C  camera frame: x right, y down, z forward (optical axis).
// Names carry their frames: q_WB rotates body vectors into W, p_W is a position in W, a_B is a specific force
// measured in B. Timestamps are integer nanoseconds everywhere inside vigil.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vigil {

// Converts between integer nanoseconds and seconds.
inline double NsToS(int64_t t_ns) { return static_cast<double>(t_ns) * 1e-9; }
int64_t SToNs(double t_s);

// One IMU measurement: gyro rate w_B [rad/s] and specific force a_B [m/s^2], both in B.
struct ImuSample {
  int64_t t_ns = 0;
  Eigen::Vector3d w_B = Eigen::Vector3d::Zero();
  Eigen::Vector3d a_B = Eigen::Vector3d::Zero();

  // Axis i in the imu.csv column order wx, wy, wz, ax, ay, az.
  double axis(int i) const { return i < 3 ? w_B[i] : a_B[i - 3]; }
  double& axis(int i) { return i < 3 ? w_B[i] : a_B[i - 3]; }
};
using ImuStream = std::vector<ImuSample>;

// The six IMU axes in imu.csv column order.
enum class ImuAxis : int { kWx = 0, kWy, kWz, kAx, kAy, kAz };
inline constexpr int kNumImuAxes = 6;
// "wx" ... "az"; the names used in configs and glitches.csv.
const char* ImuAxisName(ImuAxis axis);
// Parses "wx" ... "az"; returns false for anything else.
bool ParseImuAxis(const std::string& name, ImuAxis* axis);

// Full navigation state of the body: pose, velocity and the IMU biases in effect.
struct NavState {
  int64_t t_ns = 0;
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d b_g = Eigen::Vector3d::Zero();  // gyro bias [rad/s]
  Eigen::Vector3d b_a = Eigen::Vector3d::Zero();  // accelerometer bias [m/s^2]
};

// A timestamped body pose in W (one row of a TUM / rpg trajectory file).
struct StampedPose {
  int64_t t_ns = 0;
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
};
using Trajectory = std::vector<StampedPose>;

// A 3-D point landmark in W.
struct Landmark {
  int id = 0;
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
};

// One observation of a landmark (track id = landmark id) in an image, in pixels.
struct FeatureObservation {
  int id = 0;
  Eigen::Vector2d uv_px = Eigen::Vector2d::Zero();
};

// All observations of one camera frame.
struct CameraFrame {
  int64_t t_ns = 0;
  std::vector<FeatureObservation> features;
};

// What an injected IMU fault did to one sample (the kind column of glitches.csv).
//   offset      `offset` was added to `axis` (the paper's N(mu, sigma) glitch)
//   saturation  `axis` was clipped to the sensor's range; `offset` = clipped - unclipped value
//   drop        the sample was lost (it is not in imu.csv); t_ns is its true time, offset 0
//   duplicate   the sample carries the previous sample's timestamp; offset = written - true time [ns]
//   jitter      the sample's timestamp was shifted; offset = written - true time [ns]
// Timing kinds concern the whole sample: their axis is not meaningful (written "t" in glitches.csv).
enum class FaultKind : int { kOffset = 0, kSaturation, kDrop, kDuplicate, kJitter };
// "offset", "saturation", "drop", "duplicate", "jitter".
const char* FaultKindName(FaultKind kind);
// Parses a FaultKindName; returns false for anything else.
bool ParseFaultKind(const std::string& name, FaultKind* kind);
// Whether `kind` changes a sample's timestamp or presence rather than its values.
inline bool IsTimingFault(FaultKind kind) { return kind >= FaultKind::kDrop; }

// One injected fault on one sample (and axis, for the value kinds). t_ns is the timestamp the sample carries
// in the measured stream (for a dropped sample: its true time).
struct GlitchRecord {
  int64_t t_ns = 0;
  ImuAxis axis = ImuAxis::kAz;
  double offset = 0.0;
  FaultKind kind = FaultKind::kOffset;
};

}  // namespace vigil
