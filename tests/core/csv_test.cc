#include "core/csv.h"

#include <gtest/gtest.h>

#include "core/dataset.h"
#include "tests/core/test_util.h"

namespace vigil {
namespace {
using testing::InputErrorOf;
using testing::TempDir;

constexpr const char* kHeader = "#timestamp [ns],wx,wy,wz,ax,ay,az\n";

TEST(Csv, ImuRoundTripsExactly) {
  TempDir dir;
  ImuStream imu(3);
  for (int i = 0; i < 3; ++i) {
    imu[i].t_ns = 1000 + 5000000 * i;
    imu[i].w_B = Eigen::Vector3d(0.1 * i, -1.0 / 3.0, 1e-12);
    imu[i].a_B = Eigen::Vector3d(9.81, 2.0 / 7.0, -1e6 / 3.0);  // within kMaxAbsImuValue
  }
  const ImuStream back = ReadImuCsv(dir.File("imu.csv", ImuCsv(imu)));
  ASSERT_EQ(back.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(back[i].t_ns, imu[i].t_ns);
    EXPECT_EQ(back[i].w_B, imu[i].w_B);
    EXPECT_EQ(back[i].a_B, imu[i].a_B);
  }
}

TEST(Csv, MalformedImuFilesNameFileAndLine) {
  TempDir dir;
  const std::string empty = dir.File("empty.csv", "");
  EXPECT_EQ(InputErrorOf([&] { ReadImuCsv(empty); }), empty + ":1: empty file (expected a '#' header)");
  const std::string header_only = dir.File("h.csv", kHeader);
  EXPECT_EQ(InputErrorOf([&] { ReadImuCsv(header_only); }), header_only + ":1: no data rows");
  const std::string missing = dir.File("m.csv", std::string(kHeader) + "1,0,0,0,0,0,9.8\n2,0,0,0,0,9.8\n");
  EXPECT_EQ(InputErrorOf([&] { ReadImuCsv(missing); }), missing + ":3: expected 7 columns, found 6");
  const std::string nan = dir.File("n.csv", std::string(kHeader) + "1,0,0,0,0,0,nan\n");
  EXPECT_EQ(InputErrorOf([&] { ReadImuCsv(nan); }), nan + ":2: az: expected a finite number, got 'nan'");
  const std::string order = dir.File("o.csv", std::string(kHeader) + "5,0,0,0,0,0,1\n4,0,0,0,0,0,1\n");
  EXPECT_EQ(InputErrorOf([&] { ReadImuCsv(order); }),
            order + ":3: timestamp 4 does not increase (previous 5)");
  // A repeated timestamp (a consumer IMU's duplicated stamp) is read; the estimator keeps the first.
  const std::string repeated = dir.File("r.csv", std::string(kHeader) + "5,0,0,0,0,0,1\n5,0,0,0,0,0,2\n");
  EXPECT_EQ(ReadImuCsv(repeated).size(), 2u);
  const std::string no_header = dir.File("x.csv", "1,0,0,0,0,0,1\n");
  EXPECT_NE(InputErrorOf([&] { ReadImuCsv(no_header); }).find(no_header + ":1: expected a header"),
            std::string::npos);
  EXPECT_EQ(InputErrorOf([&] { ReadImuCsv((dir.path() / "absent.csv").string()); }),
            (dir.path() / "absent.csv").string() + ": cannot open for reading: no such file");
}

TEST(Csv, AcceptsEurocStyleWhitespaceAndCrlf) {
  TempDir dir;
  const std::string path =
      dir.File("e.csv", std::string(kHeader) + "1403636579758555392, 0.1 ,0,0,0,0,9.8\r\n");
  const ImuStream imu = ReadImuCsv(path);
  ASSERT_EQ(imu.size(), 1u);
  EXPECT_EQ(imu[0].t_ns, 1403636579758555392);
  EXPECT_DOUBLE_EQ(imu[0].w_B.x(), 0.1);
}

TEST(Csv, FeaturesGroupByFrameAndKeepEmptyFrames) {
  TempDir dir;
  std::vector<CameraFrame> frames = {
      {10, {{1, {1.5, 2.5}}, {2, {3.0, 4.0}}}}, {20, {}}, {30, {{1, {5.0, 6.0}}}}};
  const std::string path = dir.File("f.csv", FeaturesCsv(frames));
  const auto back = ReadFeaturesCsv(path, {10, 20, 30, 40});
  ASSERT_EQ(back.size(), 4u);
  EXPECT_EQ(back[0].features.size(), 2u);
  EXPECT_EQ(back[1].t_ns, 20);
  EXPECT_TRUE(back[1].features.empty());
  EXPECT_EQ(back[2].features[0].uv_px, Eigen::Vector2d(5.0, 6.0));
  EXPECT_EQ(back[3].t_ns, 40);
}

TEST(Csv, TumTrajectoryRoundTrips) {
  TempDir dir;
  Trajectory t(2);
  t[0].t_ns = 1'500'000'001;
  t[0].p_W = Eigen::Vector3d(1, 2, 3);
  t[1].t_ns = 2'000'000'000;
  t[1].q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  const std::string text = TumTrajectory(t);
  EXPECT_EQ(text.substr(0, text.find('\n', 40)),
            "# timestamp tx ty tz qx qy qz qw\n1.500000001 1 2 3 0 0 0 1");
  const Trajectory back = ReadTumTrajectory(dir.File("t.txt", text));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].t_ns, t[0].t_ns);
  EXPECT_NEAR(back[1].q_WB.angularDistance(t[1].q_WB), 0.0, 1e-12);
}

}  // namespace
}  // namespace vigil
