// The ROS 1 message decoders and the image conversion of `vigil import`, on bytes built here field by field
// as the ROS 1 wire format lays them out (the bags of tests/app/import_cli_test.cc check them against
// python3-rosbag's own serialization).
#include "core/bag/ros_message.h"

#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/bag/gray_image.h"

namespace vigil::bag {
namespace {

// Serializes fields little-endian.
class Wire {
 public:
  Wire& U8(uint8_t v) { return Raw(&v, 1); }
  Wire& U32(uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<uint8_t>(v >> (8 * i)));
    return *this;
  }
  Wire& F64(double v) {
    uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof v);
    for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<uint8_t>(bits >> (8 * i)));
    return *this;
  }
  Wire& F64s(std::initializer_list<double> vs) {
    for (double v : vs) F64(v);
    return *this;
  }
  Wire& Zeros(int doubles) {
    for (int i = 0; i < doubles; ++i) F64(0.0);
    return *this;
  }
  Wire& String(const std::string& s) {
    U32(static_cast<uint32_t>(s.size()));
    return Raw(s.data(), s.size());
  }
  Wire& Header(uint32_t sec, uint32_t nsec) { return U32(7).U32(sec).U32(nsec).String("frame"); }
  Wire& Raw(const void* p, std::size_t n) {
    const auto* b = static_cast<const uint8_t*>(p);
    bytes.insert(bytes.end(), b, b + n);
    return *this;
  }
  std::vector<uint8_t> bytes;
};

std::vector<uint8_t> Imu(uint32_t sec, uint32_t nsec) {
  Wire w;
  w.Header(sec, nsec)
      .F64s({0, 0, 0, 1})
      .Zeros(9)
      .F64s({0.1, -0.2, 0.3})
      .Zeros(9)
      .F64s({1.5, 2.5, 9.81})
      .Zeros(9);
  return w.bytes;
}

std::string ErrorOf(const std::vector<uint8_t>& bytes) {
  try {
    DecodeImu(bytes.data(), bytes.size());
  } catch (const MessageError& e) {
    return e.what();
  }
  return "";
}

TEST(RosMessage, ImuFieldsAndStamp) {
  const std::vector<uint8_t> bytes = Imu(1403715273, 262142976);
  const ImuSample s = DecodeImu(bytes.data(), bytes.size());
  EXPECT_EQ(s.t_ns, 1403715273262142976);
  EXPECT_EQ(s.w_B, Eigen::Vector3d(0.1, -0.2, 0.3));
  EXPECT_EQ(s.a_B, Eigen::Vector3d(1.5, 2.5, 9.81));
}

TEST(RosMessage, ShortLongOrCorruptBytesAreRefused) {
  std::vector<uint8_t> bytes = Imu(1, 0);
  bytes.pop_back();
  EXPECT_NE(ErrorOf(bytes).find("more needed"), std::string::npos) << ErrorOf(bytes);
  bytes = Imu(1, 0);
  bytes.push_back(0);
  EXPECT_NE(ErrorOf(bytes).find("1 bytes left over"), std::string::npos) << ErrorOf(bytes);
  EXPECT_NE(ErrorOf(Imu(1, 1000000000)).find("nsec 1000000000 is not below 1e9"), std::string::npos);
  // A string length beyond the message.
  Wire w;
  w.U32(0).U32(0).U32(0).U32(0xffffffff);
  EXPECT_NE(ErrorOf(w.bytes).find("more needed"), std::string::npos);
}

TEST(RosMessage, PoseTypes) {
  Wire pose, transform, odometry;
  pose.Header(2, 5).F64s({1, 2, 3, 0, 0, 0.6, 0.8});
  transform.Header(2, 5).String("body").F64s({1, 2, 3, 0, 0, 0.6, 0.8});
  odometry.Header(2, 5)
      .String("body")
      .F64s({1, 2, 3, 0, 0, 0.6, 0.8})
      .Zeros(36)
      .F64s({4, 5, 6, 7, 8, 9})
      .Zeros(36);
  for (const auto& [type, w] :
       {std::pair{kPoseStampedType.name, pose}, std::pair{kTransformStampedType.name, transform},
        std::pair{kOdometryType.name, odometry}}) {
    SCOPED_TRACE(type);
    const PoseMessage m = DecodePose(type, w.bytes.data(), w.bytes.size());
    EXPECT_EQ(m.t_ns, 2000000005);
    EXPECT_EQ(m.p_W, Eigen::Vector3d(1, 2, 3));
    EXPECT_EQ(m.q_WB.coeffs(), Eigen::Vector4d(0, 0, 0.6, 0.8));  // x y z w
    EXPECT_EQ(m.v_B.has_value(), std::string(type) == kOdometryType.name);
    if (m.v_B) {
      EXPECT_EQ(*m.v_B, Eigen::Vector3d(4, 5, 6));
    }
  }
  std::string md5;
  EXPECT_TRUE(IsPoseType("nav_msgs/Odometry", &md5));
  EXPECT_EQ(md5, kOdometryType.md5);
  EXPECT_FALSE(IsPoseType("geometry_msgs/PointStamped"));
}

ImageMessage Image(const std::string& encoding, uint32_t width, uint32_t height, uint32_t step,
                   const std::vector<uint8_t>& pixels, bool big_endian = false) {
  Wire w;
  w.Header(3, 0).U32(height).U32(width).String(encoding).U8(big_endian ? 1 : 0).U32(step);
  w.U32(static_cast<uint32_t>(pixels.size())).Raw(pixels.data(), pixels.size());
  static std::vector<uint8_t> keep;  // the message is a view of these bytes
  keep = w.bytes;
  return DecodeImage(keep.data(), keep.size());
}

TEST(GrayImage, EncodingsBecomeEightBitGray) {
  // mono8 with a padded step: the padding is not part of the image.
  cv::Mat g = ToGray8(Image("mono8", 2, 2, 3, {10, 20, 99, 30, 40, 99}));
  ASSERT_EQ(g.type(), CV_8UC1);
  EXPECT_EQ(g.at<uint8_t>(0, 1), 20);
  EXPECT_EQ(g.at<uint8_t>(1, 0), 30);
  // mono16: v / 257, in either byte order.
  g = ToGray8(Image("mono16", 2, 1, 4, {0xff, 0xff, 0x01, 0x01}));
  EXPECT_EQ(g.at<uint8_t>(0, 0), 255);
  EXPECT_EQ(g.at<uint8_t>(0, 1), 1);
  g = ToGray8(Image("mono16", 1, 1, 2, {0x02, 0x02}, /*big_endian=*/true));
  EXPECT_EQ(g.at<uint8_t>(0, 0), 2);
  g = ToGray8(Image("mono16", 1, 1, 2, {0x00, 0x80}, true));  // 0x0080 = 128 -> 0
  EXPECT_EQ(g.at<uint8_t>(0, 0), 0);
  // Colour: BT.601 luma; rgb8 and bgr8 differ by the channel order.
  EXPECT_EQ(ToGray8(Image("rgb8", 1, 1, 3, {255, 0, 0})).at<uint8_t>(0, 0), 76);  // 0.299 * 255
  EXPECT_EQ(ToGray8(Image("bgr8", 1, 1, 3, {255, 0, 0})).at<uint8_t>(0, 0), 29);  // 0.114 * 255
  EXPECT_EQ(ToGray8(Image("rgb8", 1, 1, 3, {77, 77, 77})).at<uint8_t>(0, 0), 77);
}

std::string GrayError(const ImageMessage& image) {
  try {
    ToGray8(image);
  } catch (const MessageError& e) {
    return e.what();
  }
  return "";
}

TEST(GrayImage, WhatCannotBeConvertedIsRefused) {
  EXPECT_EQ(GrayError(Image("bayer_rggb8", 1, 1, 1, {0})),
            "encoding 'bayer_rggb8' is not supported (mono8, mono16, rgb8, bgr8, rgba8, bgra8)");
  EXPECT_EQ(GrayError(Image("mono8", 2, 2, 2, {1, 2, 3})), "data holds 3 bytes, step x height is 4");
  EXPECT_EQ(GrayError(Image("rgb8", 2, 1, 4, {1, 2, 3, 4})), "step 4 is shorter than a row of 6 bytes");
  EXPECT_NE(GrayError(Image("mono8", 0, 1, 0, {})).find("image of 0 x 1 px"), std::string::npos);
}

}  // namespace
}  // namespace vigil::bag
