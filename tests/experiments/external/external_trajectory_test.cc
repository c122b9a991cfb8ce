#include "experiments/external/external_trajectory.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
using vigil::testing::TempDir;

constexpr int64_t kFirst = 1000000000, kLast = 5000000000;  // a recording from 1 s to 5 s

ExternalTrajectory Read(const TempDir& tmp, const std::string& text,
                        TrajectoryFormat format = TrajectoryFormat::kTum,
                        TimeUnit unit = TimeUnit::kSeconds) {
  return ReadExternalTrajectory(tmp.File("t.txt", text), format, unit, kFirst, kLast);
}

TEST(ExternalTrajectory, ReadsTumSecondsExactlyToTheNanosecond) {
  TempDir tmp;
  const ExternalTrajectory t = Read(tmp,
                                    "# timestamp tx ty tz qx qy qz qw\n1.000000001 1 2 3 0 0 0 1\n"
                                    "  2.123456789\t4 5 6 0 0 1 0 \n3.9999999995 0 0 0 0 0 0 1\n");
  ASSERT_EQ(t.failure, "");
  ASSERT_EQ(t.trajectory.size(), 3u);
  EXPECT_EQ(t.trajectory[0].t_ns, 1000000001);
  EXPECT_EQ(t.trajectory[1].t_ns, 2123456789);
  EXPECT_EQ(t.trajectory[2].t_ns, 4000000000);  // rounded at the tenth digit
  EXPECT_EQ(t.trajectory[1].p_W.y(), 5.0);
  EXPECT_EQ(t.trajectory[1].q_WB.z(), 1.0);
  EXPECT_EQ(t.trajectory[2].q_WB.w(), 1.0);
}

TEST(ExternalTrajectory, IgnoresFurtherTumColumns) {
  TempDir tmp;
  const ExternalTrajectory t =
      Read(tmp, "# timestamp(s) tx ty tz qx qy qz qw Pr11 Pr12\n1.5 1 2 3 0 0 0 1 0.01 0\n");
  ASSERT_EQ(t.failure, "");
  ASSERT_EQ(t.trajectory.size(), 1u);
  EXPECT_EQ(t.trajectory[0].p_W.z(), 3.0);
}

TEST(ExternalTrajectory, ReadsNanosecondsWrittenAsFixedPointNumbers) {
  TempDir tmp;
  const ExternalTrajectory t =
      Read(tmp, "1500000000.000000 1 2 3 0 0 0 1\n", TrajectoryFormat::kTum, TimeUnit::kNanoseconds);
  ASSERT_EQ(t.failure, "");
  EXPECT_EQ(t.trajectory[0].t_ns, 1500000000);
}

TEST(ExternalTrajectory, ReadsEurocNanosecondsWithExtraColumns) {
  TempDir tmp;
  const ExternalTrajectory t = Read(tmp, "#timestamp,x,y,z,qw,qx,qy,qz,vx\n2000000000,1,2,3,1,0,0,0,9\n",
                                    TrajectoryFormat::kEuroc, TimeUnit::kNanoseconds);
  ASSERT_EQ(t.failure, "");
  ASSERT_EQ(t.trajectory.size(), 1u);
  EXPECT_EQ(t.trajectory[0].t_ns, 2000000000);
  EXPECT_EQ(t.trajectory[0].q_WB.w(), 1.0);
}

TEST(ExternalTrajectory, EveryBadFileIsAReasonNotACrash) {
  TempDir tmp;
  const auto failure = [&](const std::string& text, TimeUnit unit = TimeUnit::kSeconds) {
    return Read(tmp, text, TrajectoryFormat::kTum, unit).failure;
  };
  EXPECT_NE(failure("").find("empty"), std::string::npos);
  EXPECT_NE(failure("# only a comment\n").find("empty"), std::string::npos);
  EXPECT_NE(failure("1 2 3\n").find("t.txt:1: 3 columns"), std::string::npos);
  EXPECT_NE(failure("2 nan 0 0 0 0 0 1\n").find("t.txt:1: column 2"), std::string::npos);
  EXPECT_NE(failure("2 inf 0 0 0 0 0 1\n").find("not a finite number"), std::string::npos);
  EXPECT_NE(failure("x 0 0 0 0 0 0 1\n").find("timestamp 'x'"), std::string::npos);
  EXPECT_NE(failure("2 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n").find("t.txt:2: timestamps are not strictly"),
            std::string::npos);
  EXPECT_NE(failure("3 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n").find("not strictly increasing"), std::string::npos);
  EXPECT_NE(failure("2 0 0 0 0 0 0 0\n").find("t.txt:1: quaternion is not unit (norm 0"), std::string::npos);
  // The rule of every pose reader (core/pose_checks.h): a 3x quaternion is refused, not normalized.
  EXPECT_NE(failure("2 0 0 0 0 0 0 3\n").find("t.txt:1: quaternion is not unit (norm 3"), std::string::npos);
  EXPECT_NE(failure("2 0 0 0 0 0 0 1.002\n").find("not unit"), std::string::npos);
  EXPECT_EQ(failure("2 0 0 0 0 0 0 1.0005\n"), "");
  EXPECT_NE(failure("2 1e7 0 0 0 0 0 1\n").find("beyond the limit"), std::string::npos);
  // Nanoseconds where seconds are expected: far outside the recording.
  EXPECT_NE(failure("2000000000 0 0 0 0 0 0 1\n").find("outside the recording"), std::string::npos);
  EXPECT_NE(failure("9.5 0 0 0 0 0 0 1\n").find("unit mix-up"), std::string::npos);
  // Seconds where nanoseconds are expected: a few ns after the epoch, also outside.
  EXPECT_NE(failure("2.5 0 0 0 0 0 0 1\n", TimeUnit::kNanoseconds).find("outside the recording"),
            std::string::npos);
  // Seconds read as nanoseconds on a recording that starts at 0: every time lies inside it, but the rows
  // collapse onto one nanosecond; the hint names the unit, not the order.
  const auto from_zero = [&](const std::string& text, TimeUnit unit) {
    return ReadExternalTrajectory(tmp.File("z.txt", text), TrajectoryFormat::kTum, unit, 0, 20000000000)
        .failure;
  };
  EXPECT_EQ(from_zero("0.000 0 0 0 0 0 0 1\n0.050 0 0 0 0 0 0 1\n", TimeUnit::kNanoseconds),
            "z.txt:2: timestamp 0.050 lies 0 ns after the previous row's, less than 1 us: a unit mix-up? "
            "(estimator.external.time_unit ns reads them as nanoseconds)");
  EXPECT_NE(from_zero("0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n", TimeUnit::kNanoseconds).find("a unit mix-up?"),
            std::string::npos);
  EXPECT_EQ(from_zero("0.05 0 0 0 0 0 0 1\n0.05 0 0 0 0 0 0 1\n", TimeUnit::kNanoseconds)
                .find("timestamps are not strictly increasing"),
            std::string("z.txt:2: ").size());
  EXPECT_EQ(from_zero("0.0 0 0 0 0 0 0 1\n0.05 0 0 0 0 0 0 1\n", TimeUnit::kSeconds), "");
  // A reason quotes the file's bytes on one printable line (found by fuzz/fuzz_external_trajectory.cc).
  EXPECT_EQ(failure("2 0 0 0 0 0 0 1\v\x01\n"), "t.txt:1: column 8: '1\\x0b\\x01' is not a finite number");
  EXPECT_NE(ReadExternalTrajectory(tmp.path() / "absent.txt", TrajectoryFormat::kTum, TimeUnit::kSeconds,
                                   kFirst, kLast)
                .failure.find("wrote no trajectory"),
            std::string::npos);
}

}  // namespace
}  // namespace vigil::experiments
