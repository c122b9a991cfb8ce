// The ROS 1 messages `vigil import` reads, decoded from their serialized bytes (the ROS 1 wire format:
// little-endian integers and IEEE doubles, a string or variable-length array as a uint32 length then its
// elements, fixed-length arrays without a length). Only the fields vigil uses are kept; no ROS installation
// is needed.
//
// A message type is identified by its name and the MD5 sum of its definition (what a bag's connection header
// records): a topic whose MD5 differs from the one below has another layout and is refused, never decoded.
// Every decoder throws MessageError with a reason (no file or topic: the caller adds them) when the bytes
// end early, are left over, or hold a value vigil cannot use (a time whose nanoseconds are 1e9 or more).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/types.h"

namespace vigil::bag {

class MessageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RosType {
  const char* name;
  const char* md5;
};
inline constexpr RosType kImuType{"sensor_msgs/Imu", "6a62c6daae103f4ff57a132d6f95cec2"};
inline constexpr RosType kImageType{"sensor_msgs/Image", "060021388200f6f0f447d0fcd9c64743"};
inline constexpr RosType kPoseStampedType{"geometry_msgs/PoseStamped", "d3812c3cbc69362b77dc0b19b345f8f5"};
inline constexpr RosType kTransformStampedType{"geometry_msgs/TransformStamped",
                                               "b5764a33bfeb3588febc2682852579b0"};
inline constexpr RosType kOdometryType{"nav_msgs/Odometry", "cd5e73d190d741a2f92e81eda573aca7"};

// sensor_msgs/Image: a view of the pixel bytes inside the message's buffer.
struct ImageMessage {
  int64_t t_ns = 0;  // header.stamp
  uint32_t width = 0, height = 0, step = 0;
  std::string encoding;
  bool big_endian = false;
  const uint8_t* data = nullptr;
  std::size_t size = 0;
};

// A ground-truth pose: PoseStamped (the pose), TransformStamped (the child frame in the parent frame) or
// Odometry (its pose, and its linear velocity, expressed in the child frame as ROS defines it).
struct PoseMessage {
  int64_t t_ns = 0;  // header.stamp
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  std::optional<Eigen::Vector3d> v_B;  // Odometry only
};

// sensor_msgs/Imu: header.stamp, angular_velocity -> w_B, linear_acceleration -> a_B (orientation and the
// covariances are not used).
ImuSample DecodeImu(const uint8_t* data, std::size_t size);
ImageMessage DecodeImage(const uint8_t* data, std::size_t size);
// `type` is one of the three ground-truth types above (by name).
PoseMessage DecodePose(const std::string& type, const uint8_t* data, std::size_t size);

// Whether `type` names one of the ground-truth types DecodePose reads; `md5` gets its MD5 sum.
bool IsPoseType(const std::string& type, std::string* md5 = nullptr);

}  // namespace vigil::bag
