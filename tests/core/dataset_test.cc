#include "core/dataset.h"

#include <limits>

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
    x.p_W = Eigen::Vector3d(0.25 * i, 0, 0);  // 50 m/s
    d.groundtruth.push_back(x);
  }
  d.imu_clean = d.imu;
  d.imu[4].a_B.z() += 50.0;
  d.glitches.push_back({d.imu[4].t_ns, ImuAxis::kAz, 50.0});
  d.landmarks = {{0, {1, 2, 3}}, {1, {4, 5, 6}}};
  d.camera.rate_hz = 40.0;  // a frame every 25 ms: 0, 25, 50, 75, 100 ms
  d.frames = {{0, {{0, {10, 20}}}},
              {25'000'000, {}},
              {50'000'000, {{1, {30, 40}}, {0, {11, 21}}}},
              {75'000'000, {}},
              {100'000'000, {}}};
  WriteDataset(tmp.path(), d);
  const Dataset back = ReadDataset(tmp.path());
  ASSERT_EQ(back.imu.size(), 21u);
  EXPECT_EQ(back.imu[4].a_B, d.imu[4].a_B);
  EXPECT_EQ(back.imu_clean[4].a_B, d.imu_clean[4].a_B);
  ASSERT_EQ(back.glitches.size(), 1u);
  EXPECT_EQ(back.glitches[0].axis, ImuAxis::kAz);
  EXPECT_EQ(back.groundtruth[20].p_W, Eigen::Vector3d(5, 0, 0));
  EXPECT_EQ(back.landmarks[1].p_W, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(back.camera.rate_hz, 40.0);
  ASSERT_EQ(back.frames.size(), 5u);
  EXPECT_EQ(back.frames[2].features.size(), 2u);
  EXPECT_TRUE(back.frames[4].features.empty());
}

// A valid dataset directory with a few files to corrupt.
Dataset SmallDataset() {
  Dataset d;
  for (int i = 0; i < 21; ++i) {
    ImuSample s;
    s.t_ns = i * 5'000'000;
    s.a_B = Eigen::Vector3d(0, 0, 9.81);
    d.imu.push_back(s);
    NavState x;
    x.t_ns = s.t_ns;
    x.p_W = Eigen::Vector3d(0.25 * i, 0, 0);  // 50 m/s
    d.groundtruth.push_back(x);
  }
  d.imu_clean = d.imu;
  d.landmarks = {{0, {1, 2, 3}}, {1, {4, 5, 6}}};
  d.camera.rate_hz = 40.0;
  d.frames = {{0, {{0, {10, 20}}}},
              {25'000'000, {}},
              {50'000'000, {{1, {30, 40}}, {0, {11, 21}}}},
              {75'000'000, {}},
              {100'000'000, {}}};
  return d;
}

std::string ReadError(const TempDir& tmp, const std::string& file, const std::string& content) {
  WriteDataset(tmp.path(), SmallDataset());
  tmp.File(file, content);
  return testing::InputErrorOf([&] { ReadDataset(tmp.path()); });
}

TEST(Dataset, FeatureValuesAreChecked) {
  TempDir tmp;
  const std::string header = "#timestamp [ns],id,u [px],v [px]\n";
  EXPECT_NE(
      ReadError(tmp, "features.csv", header + "0,0,1e308,20\n").find("features.csv:2: pixel (1e+308, 20)"),
      std::string::npos);
  EXPECT_NE(ReadError(tmp, "features.csv", header + "0,0,-1e9,20\n").find("outside the 640 x 640 image"),
            std::string::npos);
  EXPECT_NE(ReadError(tmp, "features.csv", header + "0,7,10,20\n").find("id: 7 is not a landmark"),
            std::string::npos);
  EXPECT_NE(ReadError(tmp, "features.csv", header + "0,-1,10,20\n").find("id: -1 is not an id"),
            std::string::npos);
  EXPECT_NE(ReadError(tmp, "features.csv", header + "0,0,10,20\n0,0,11,21\n").find("observed twice"),
            std::string::npos);
  EXPECT_NE(ReadError(tmp, "features.csv", header + "900000000,0,10,20\n").find("outside the camera frames"),
            std::string::npos);
}

// Frames come from frames.csv at their own times (jittered, with a dropped one: nothing on a grid), never
// reconstructed from camera.yaml's rate; without frames.csv, the frames are features.csv's timestamps.
TEST(Dataset, FramesAreReadAtTheirRecordedTimesAndNeverPadded) {
  TempDir tmp;
  Dataset d = SmallDataset();
  d.frames = {{0, {{0, {10, 20}}}}, {24'999'872, {}}, {75'000'128, {{1, {30, 40}}}}, {99'000'000, {}}};
  WriteDataset(tmp.path(), d);
  Dataset back = ReadDataset(tmp.path());
  ASSERT_EQ(back.frames.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(back.frames[k].t_ns, d.frames[k].t_ns);
  EXPECT_TRUE(back.frames[3].features.empty());
  std::filesystem::remove(tmp.path() / "frames.csv");
  back = ReadDataset(tmp.path());
  ASSERT_EQ(back.frames.size(), 2u);
  EXPECT_EQ(back.frames[1].t_ns, 75'000'128);
}

TEST(Dataset, FrameTimesAreChecked) {
  TempDir tmp;
  const std::string header = "#timestamp [ns],id,u [px],v [px]\n";
  EXPECT_NE(ReadError(tmp, "features.csv", header + "25000001,0,10,20\n")
                .find("features.csv:2: timestamp 25000001 is not the time of a camera frame (frames.csv)"),
            std::string::npos);
  EXPECT_NE(ReadError(tmp, "frames.csv", "#timestamp [ns]\n0\n100000001\n")
                .find("frames.csv:3: timestamp 100000001 is outside the IMU's time span (0 .. 100000000"),
            std::string::npos);
  EXPECT_NE(
      ReadError(tmp, "frames.csv", "#timestamp [ns]\n0\n0\n").find("frames.csv:3: timestamp 0 does not"),
      std::string::npos);
}

TEST(Dataset, GroundTruthValuesAreChecked) {
  TempDir tmp;
  Dataset d = SmallDataset();
  std::string one_row = GroundTruthCsv({d.groundtruth.front()});
  EXPECT_NE(ReadError(tmp, "groundtruth.csv", one_row).find("groundtruth.csv:2: one ground-truth row"),
            std::string::npos);
  d.groundtruth[3].p_W.x() = 1e308;
  EXPECT_NE(
      ReadError(tmp, "groundtruth.csv", GroundTruthCsv(d.groundtruth)).find("groundtruth.csv:5: p_RS_R_x"),
      std::string::npos);
}

TEST(Dataset, LandmarkIdsAreDistinctAndValid) {
  TempDir tmp;
  EXPECT_NE(ReadError(tmp, "landmarks.csv", "#id,x,y,z\n0,1,2,3\n0,4,5,6\n")
                .find("landmarks.csv:3: id: 0 listed twice"),
            std::string::npos);
  EXPECT_NE(ReadError(tmp, "landmarks.csv", "#id,x,y,z\n4294967296,1,2,3\n").find("is not an id"),
            std::string::npos);
}

TEST(Dataset, ImuGapsAndValuesHaveLimits) {
  TempDir tmp;
  Dataset d = SmallDataset();
  d.imu[5].t_ns = d.imu[4].t_ns + 1'000'000'000'000'000;  // 1e6 s later
  for (std::size_t i = 6; i < d.imu.size(); ++i) d.imu[i].t_ns = d.imu[i - 1].t_ns + 5'000'000;
  EXPECT_NE(ReadError(tmp, "imu.csv", ImuCsv(d.imu)).find("imu.csv:7: timestamp"), std::string::npos);
  d = SmallDataset();
  d.imu[2].a_B.x() = 1e300;
  EXPECT_NE(ReadError(tmp, "imu.csv", ImuCsv(d.imu)).find("imu.csv:4: a_RS_S_x [m s^-2]: 1e+300 is beyond"),
            std::string::npos);
}

TEST(Dataset, NonFiniteNumbersAreNeverWritten) {
  Dataset d = SmallDataset();
  d.imu[2].a_B.x() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(testing::InputErrorOf([&] { ImuCsv(d.imu, "out/imu.csv"); }),
            "out/imu.csv:4: a_RS_S_x [m s^-2]: cannot write the non-finite value inf (vigil never writes inf "
            "or nan): an input value or setting is out of range");
}

TEST(Dataset, TumTrajectoryValuesAreChecked) {
  TempDir tmp;
  const std::string path = tmp.File("t.txt", "0 1e308 0 0 0 0 0 1\n");
  EXPECT_NE(testing::InputErrorOf([&] { ReadTumTrajectory(path); }).find(":1: position: 1e+308 m is beyond"),
            std::string::npos);
  const std::string late = tmp.File("late.txt", "1e300 0 0 0 0 0 0 1\n");
  EXPECT_NE(testing::InputErrorOf([&] { ReadTumTrajectory(late); }).find("timestamp"), std::string::npos);
}

}  // namespace
}  // namespace vigil
