#include "core/dataset.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil {
namespace {
using testing::TempDir;

TEST(Dataset, DirectoryRoundTrips) {
  TempDir tmp;
  Dataset d;
  for (int i = 0; i < 21; ++i) {
    ImuSample s;
    s.t_ns = i * 5'000'000;
    s.a_B = Eigen::Vector3d(0, 0, 9.81 + 0.01 * i);
    d.imu.push_back(s);
    NavState x;
    x.t_ns = s.t_ns;
    x.p_W = Eigen::Vector3d(i, 0, 0);
    d.groundtruth.push_back(x);
  }
  d.imu_clean = d.imu;
  d.imu[4].a_B.z() += 50.0;
  d.glitches.push_back({d.imu[4].t_ns, ImuAxis::kAz, 50.0});
  d.landmarks = {{0, {1, 2, 3}}, {1, {4, 5, 6}}};
  d.camera.rate_hz = 40.0;  // a frame every 25 ms: 0, 25, 50, 75, 100 ms
  d.frames = {{0, {{0, {10, 20}}}}, {25'000'000, {}}, {50'000'000, {{1, {30, 40}}, {0, {11, 21}}}},
              {75'000'000, {}}, {100'000'000, {}}};
  WriteDataset(tmp.path(), d);
  const Dataset back = ReadDataset(tmp.path());
  ASSERT_EQ(back.imu.size(), 21u);
  EXPECT_EQ(back.imu[4].a_B, d.imu[4].a_B);
  EXPECT_EQ(back.imu_clean[4].a_B, d.imu_clean[4].a_B);
  ASSERT_EQ(back.glitches.size(), 1u);
  EXPECT_EQ(back.glitches[0].axis, ImuAxis::kAz);
  EXPECT_EQ(back.groundtruth[20].p_W, Eigen::Vector3d(20, 0, 0));
  EXPECT_EQ(back.landmarks[1].p_W, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(back.camera.rate_hz, 40.0);
  ASSERT_EQ(back.frames.size(), 5u);
  EXPECT_EQ(back.frames[2].features.size(), 2u);
  EXPECT_TRUE(back.frames[4].features.empty());
}

}  // namespace
}  // namespace vigil
