// imu_axis.csv: what a run records for its IMU figures, written and read back exactly; bad files rejected.
#include "experiments/runs/imu_axis_record.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "core/output.h"
#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {

ImuStream Stream(double offset) {
  ImuStream imu(4);
  for (std::size_t i = 0; i < imu.size(); ++i) {
    imu[i].t_ns = 1'000'000'000 + static_cast<int64_t>(i) * 5'000'000;
    imu[i].w_B = Eigen::Vector3d(0.1 * i, 0.2, 0.3) * (1.0 + offset);
    imu[i].a_B = Eigen::Vector3d(1.0, 2.0, 9.81 + offset + 1.0 / 3.0 * i);
  }
  return imu;
}

TEST(ImuAxisRecord, RoundTripsExactly) {
  vigil::testing::TempDir tmp;
  const ImuStream raw = Stream(5.0), clean = Stream(0.0), mitigated = Stream(0.5);
  const std::vector<uint8_t> flagged = {0, 1, 1, 0};
  const ImuAxisRecord record = MakeImuAxisRecord(ImuAxis::kAz, raw, &clean, mitigated, flagged);
  ASSERT_EQ(record.raw.size(), 4u);
  EXPECT_EQ(record.raw[2], raw[2].a_B.z());
  EXPECT_EQ(record.clean[2], clean[2].a_B.z());
  EXPECT_EQ(record.mitigated[2], mitigated[2].a_B.z());
  const std::string text = ImuAxisCsv(record);
  EXPECT_EQ(text.substr(0, text.find('\n')), "#timestamp [ns],raw az,clean az,mitigated az,flagged");
  WriteFileAtomic(tmp.path() / "imu_axis.csv", text);
  const ImuAxisRecord back = ReadImuAxisCsv((tmp.path() / "imu_axis.csv").string());
  EXPECT_EQ(back.axis, ImuAxis::kAz);
  EXPECT_EQ(back.t_ns, record.t_ns);
  EXPECT_EQ(back.raw, record.raw);
  EXPECT_EQ(back.clean, record.clean);
  EXPECT_EQ(back.mitigated, record.mitigated);
  EXPECT_EQ(back.flagged, flagged);
}

TEST(ImuAxisRecord, WithoutCleanStreamHasFourColumns) {
  vigil::testing::TempDir tmp;
  const ImuStream raw = Stream(1.0);
  const ImuAxisRecord record = MakeImuAxisRecord(ImuAxis::kWx, raw, nullptr, raw, {0, 0, 0, 0});
  const std::string text = ImuAxisCsv(record);
  EXPECT_EQ(text.substr(0, text.find('\n')), "#timestamp [ns],raw wx,mitigated wx,flagged");
  WriteFileAtomic(tmp.path() / "imu_axis.csv", text);
  const ImuAxisRecord back = ReadImuAxisCsv((tmp.path() / "imu_axis.csv").string());
  EXPECT_EQ(back.axis, ImuAxis::kWx);
  EXPECT_TRUE(back.clean.empty());
  EXPECT_EQ(back.raw, record.raw);
  EXPECT_EQ(back.raw[3], raw[3].w_B.x());
}

TEST(ImuAxisRecord, RejectsMismatchedStreams) {
  const ImuStream raw = Stream(1.0);
  EXPECT_THROW(MakeImuAxisRecord(ImuAxis::kAz, raw, nullptr, raw, {0, 0}), std::invalid_argument);
  const ImuStream short_clean(2);
  EXPECT_THROW(MakeImuAxisRecord(ImuAxis::kAz, raw, &short_clean, raw, {0, 0, 0, 0}), std::invalid_argument);
}

TEST(ImuAxisRecord, BadFilesNameFileAndLine) {
  vigil::testing::TempDir tmp;
  const auto error_of = [&](const std::string& text) {
    WriteFileAtomic(tmp.path() / "imu_axis.csv", text);
    return vigil::testing::InputErrorOf([&] { ReadImuAxisCsv((tmp.path() / "imu_axis.csv").string()); });
  };
  EXPECT_NE(error_of("#timestamp [ns],raw az,clean ay,mitigated az,flagged\n").find("imu_axis.csv:1: header"),
            std::string::npos);
  EXPECT_NE(error_of("#timestamp [ns],raw q,mitigated q,flagged\n").find("imu_axis.csv:1: header"),
            std::string::npos);
  EXPECT_NE(
      error_of("#timestamp [ns],raw az,mitigated az,flagged\n1,2,3,2\n").find("imu_axis.csv:2: flagged"),
      std::string::npos);
  EXPECT_NE(error_of("#timestamp [ns],raw az,mitigated az,flagged\n2,2,3,0\n2,2,3,0\n")
                .find("imu_axis.csv:3: timestamp"),
            std::string::npos);
  EXPECT_NE(error_of("#timestamp [ns],raw az,mitigated az,flagged\n2,nan,3,0\n").find("imu_axis.csv:2:"),
            std::string::npos);
}

}  // namespace
}  // namespace vigil::experiments
