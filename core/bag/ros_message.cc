#include "core/bag/ros_message.h"

#include <cstring>

namespace vigil::bag {
namespace {

// Reads the ROS 1 wire format front to back; every read checks that the bytes are there.
class WireReader {
 public:
  WireReader(const uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  const uint8_t* Bytes(std::size_t n) {
    if (n > size_ - at_)
      throw MessageError("message ends after " + std::to_string(size_) + " bytes, " + std::to_string(n) +
                         " more needed at byte " + std::to_string(at_) + " (truncated or another layout)");
    const uint8_t* p = data_ + at_;
    at_ += n;
    return p;
  }
  uint8_t U8() { return *Bytes(1); }
  uint32_t U32() {
    const uint8_t* p = Bytes(4);
    return uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 | uint32_t{p[3]} << 24;
  }
  double F64() {
    const uint8_t* p = Bytes(8);
    uint64_t bits = 0;
    for (int i = 7; i >= 0; --i) bits = bits << 8 | p[i];
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  std::string String() {
    const uint32_t n = U32();
    const uint8_t* p = Bytes(n);
    return std::string(reinterpret_cast<const char*>(p), n);
  }
  Eigen::Vector3d Vector3() {
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) v[i] = F64();
    return v;
  }
  // geometry_msgs/Quaternion: x, y, z, w.
  Eigen::Quaterniond Quaternion() {
    const Eigen::Vector3d xyz = Vector3();
    return Eigen::Quaterniond(F64(), xyz.x(), xyz.y(), xyz.z());
  }
  void SkipDoubles(std::size_t n) { Bytes(8 * n); }
  // std_msgs/Header: seq, stamp (sec, nsec), frame_id; returns the stamp [ns].
  int64_t HeaderStamp() {
    U32();
    const uint32_t sec = U32(), nsec = U32();
    if (nsec >= 1000000000u)
      throw MessageError("header.stamp: nsec " + std::to_string(nsec) +
                         " is not below 1e9 (corrupt message)");
    String();
    return int64_t{sec} * 1000000000 + nsec;
  }
  void ExpectEnd() const {
    if (at_ != size_)
      throw MessageError(std::to_string(size_ - at_) + " bytes left over after the message's " +
                         std::to_string(at_) + " (another layout)");
  }

 private:
  const uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

// geometry_msgs/Pose: Point position, Quaternion orientation.
void ReadPose(WireReader& r, PoseMessage& m) {
  m.p_W = r.Vector3();
  m.q_WB = r.Quaternion();
}

}  // namespace

ImuSample DecodeImu(const uint8_t* data, std::size_t size) {
  WireReader r(data, size);
  ImuSample s;
  s.t_ns = r.HeaderStamp();
  r.Quaternion();    // orientation
  r.SkipDoubles(9);  // orientation_covariance
  s.w_B = r.Vector3();
  r.SkipDoubles(9);  // angular_velocity_covariance
  s.a_B = r.Vector3();
  r.SkipDoubles(9);  // linear_acceleration_covariance
  r.ExpectEnd();
  return s;
}

ImageMessage DecodeImage(const uint8_t* data, std::size_t size) {
  WireReader r(data, size);
  ImageMessage m;
  m.t_ns = r.HeaderStamp();
  m.height = r.U32();
  m.width = r.U32();
  m.encoding = r.String();
  m.big_endian = r.U8() != 0;
  m.step = r.U32();
  m.size = r.U32();
  m.data = r.Bytes(m.size);
  r.ExpectEnd();
  return m;
}

PoseMessage DecodePose(const std::string& type, const uint8_t* data, std::size_t size) {
  WireReader r(data, size);
  PoseMessage m;
  m.t_ns = r.HeaderStamp();
  if (type == kPoseStampedType.name) {
    ReadPose(r, m);
  } else if (type == kTransformStampedType.name) {
    r.String();  // child_frame_id
    m.p_W = r.Vector3();
    m.q_WB = r.Quaternion();
  } else if (type == kOdometryType.name) {
    r.String();  // child_frame_id
    ReadPose(r, m);
    r.SkipDoubles(36);  // pose covariance
    m.v_B = r.Vector3();
    r.Vector3();        // angular velocity
    r.SkipDoubles(36);  // twist covariance
  } else {
    throw MessageError(type + " is not a ground-truth type vigil reads");
  }
  r.ExpectEnd();
  return m;
}

bool IsPoseType(const std::string& type, std::string* md5) {
  for (const RosType& t : {kPoseStampedType, kTransformStampedType, kOdometryType}) {
    if (type != t.name) continue;
    if (md5 != nullptr) *md5 = t.md5;
    return true;
  }
  return false;
}

}  // namespace vigil::bag
