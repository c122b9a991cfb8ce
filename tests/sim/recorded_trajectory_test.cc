#include "sim/recorded_trajectory.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/format.h"
#include "core/so3.h"
#include "core/types.h"
#include "sim/cumulative_bspline.h"
#include "sim/ellipse_trajectory.h"
#include "sim/imu_synthesizer.h"
#include "tests/core/test_util.h"
#include "tests/sim/midpoint_integration.h"

namespace vigil::sim {
namespace {

namespace fs = std::filesystem;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

const fs::path kExcerpt = fs::path(VIGIL_SOURCE_DIR) / "tests/sim/data/v1_01_groundtruth_excerpt.csv";
// The shared real data, beside the repository (CI clones the repository with shared/ next to it).
const fs::path kEuroc = fs::path(VIGIL_SOURCE_DIR) / "../shared/data/euroc_v1_01";

constexpr double kPi = 3.14159265358979323846;

// Central differences of the spline itself against its analytic derivatives. The step h = 1e-5 s errs by
// h^2 / 6 times the third derivative plus rounding (1e-16 |x| / h), far below the bound.
void ExpectDerivativesMatchFiniteDifferences(const TrajectoryModel& m, double t0, double t1, double tol) {
  const double h = 1e-5;
  for (double t = t0 + 2 * h; t < t1 - 2 * h; t += (t1 - t0) / 97.3) {
    const TrajectoryState x = m.StateAt(t), xm = m.StateAt(t - h), xp = m.StateAt(t + h);
    EXPECT_LT((x.v_W - (xp.p_W - xm.p_W) / (2 * h)).norm(), tol * (1 + x.v_W.norm())) << "v_W at t = " << t;
    EXPECT_LT((x.a_W - (xp.v_W - xm.v_W) / (2 * h)).norm(), tol * (1 + x.a_W.norm())) << "a_W at t = " << t;
    const Eigen::Vector3d w_fd = LogQ(xm.q_WB.conjugate() * xp.q_WB) / (2 * h);
    EXPECT_LT((x.w_B - w_fd).norm(), tol * (1 + x.w_B.norm())) << "w_B at t = " << t;
    EXPECT_NEAR(x.q_WB.norm(), 1.0, 1e-12);
  }
}

// A spline over arbitrary control points: large rotations between them, and roll near +-pi.
class SplineModel final : public TrajectoryModel {
 public:
  explicit SplineModel(CumulativeBSpline s) : spline_(std::move(s)) {}
  TrajectoryState StateAt(double t) const override { return StateOf(spline_.Evaluate(t)); }
  double EndTime() const override { return spline_.EndTime(); }

 private:
  CumulativeBSpline spline_;
};

TEST(CumulativeBSpline, DerivativesMatchFiniteDifferences) {
  std::vector<CumulativeBSpline::ControlPoint> c(12);
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double s = static_cast<double>(i);
    c[i].p_W = Eigen::Vector3d(std::sin(0.7 * s), 0.3 * s, std::cos(1.3 * s));
    c[i].q_WB = ExpQ(Eigen::Vector3d(kPi - 0.05 + 0.1 * std::sin(s), 0.4 * std::cos(0.9 * s), 0.5 * s));
  }
  const SplineModel m(CumulativeBSpline(c, 0.1));
  EXPECT_NEAR(m.EndTime(), 0.9, 1e-12);
  ExpectDerivativesMatchFiniteDifferences(m, 0.0, m.EndTime(), 2e-5);
}

// The basis sums to the B-spline's: at u = 0 the position is (p_0 + 4 p_1 + p_2) / 6, and equal control
// points give that point with zero derivatives.
TEST(CumulativeBSpline, ReproducesTheUniformCubicBSpline) {
  std::vector<CumulativeBSpline::ControlPoint> c(5);
  for (std::size_t i = 0; i < c.size(); ++i) {
    c[i].p_W = Eigen::Vector3d(static_cast<double>(i * i), 1.0, -2.0 * static_cast<double>(i));
    c[i].q_WB = ExpQ(Eigen::Vector3d(0.1, -0.2, 0.3));
  }
  const CumulativeBSpline s(c, 0.5);
  const CumulativeBSpline::Sample x = s.Evaluate(0.5);  // segment 1, u = 0
  EXPECT_LT((x.p_W - (c[1].p_W + 4 * c[2].p_W + c[3].p_W) / 6.0).norm(), 1e-12);
  EXPECT_LT(AngleOf(x.q_WB.conjugate() * c[0].q_WB), 1e-12);
  EXPECT_LT(x.w_B.norm(), 1e-12);
}

// Poses sampled from a known smooth motion (the ellipse at 7 m/s, turned so the body flies upside down) at
// 20 Hz: the fitted spline passes within micrometres of them and follows the motion between them. Measured:
// position rms 3e-6 m, rotation rms 2e-5 deg, velocity rms 1.8 mm/s (largest at the two ends); between the
// poses 3e-6 m, 3e-8 rad, body rate 1e-7 rad/s.
TEST(RecordedTrajectory, FitsPosesOfASmoothMotion) {
  const EllipseTrajectory ellipse;
  const Eigen::Quaterniond flip = ExpQ(Eigen::Vector3d(kPi - 0.01, 0, 0));
  std::vector<TimedPose> poses;
  for (int k = 0; k <= 200; ++k) {
    const TrajectoryState x = ellipse.StateAt(0.05 * k);
    poses.emplace_back(1'000'000'000'000 + 50'000'000LL * k, x.p_W, x.q_WB * flip, x.v_W);
  }
  const RecordedTrajectory m(poses, RecordedTrajectoryOptions{});
  EXPECT_EQ(m.StartNs(), 1'000'000'000'000);
  EXPECT_NEAR(m.EndTime(), 10.0, 1e-12);
  const FitReport r = m.Fit();
  std::printf(
      "ellipse at 20 Hz: position rms %.3g m max %.3g, rotation rms %.3g deg, velocity rms %.3g m/s\n",
      r.position_rms_m, r.position_max_m, r.rotation_rms_deg, r.velocity_rms_mps);
  EXPECT_EQ(r.poses, 201u);
  EXPECT_EQ(r.control_points, 203u);
  EXPECT_NEAR(r.knot_spacing_s, 0.05, 1e-12);
  EXPECT_TRUE(r.has_velocity);
  EXPECT_LT(r.position_rms_m, 3e-5);
  EXPECT_LT(r.rotation_rms_deg, 2e-4);
  EXPECT_LT(r.velocity_rms_mps, 0.01);
  for (double t = 0.525; t < 9.5; t += 0.1) {  // between the poses
    const TrajectoryState want = ellipse.StateAt(t), got = m.StateAt(t);
    EXPECT_LT((got.p_W - want.p_W).norm(), 3e-5) << t;
    EXPECT_LT(AngleOf((want.q_WB * flip).conjugate() * got.q_WB), 1e-6) << t;
    EXPECT_LT((got.w_B - flip.conjugate() * want.w_B).norm(), 1e-5) << t;
    EXPECT_LT((got.v_W - want.v_W).norm(), 1e-4) << t;
  }
  ExpectDerivativesMatchFiniteDifferences(m, 0.0, m.EndTime(), 2e-5);
  // Without smoothing the spline interpolates the poses.
  RecordedTrajectoryOptions exact;
  exact.smoothing = 0.0;
  EXPECT_LT(RecordedTrajectory(poses, exact).Fit().position_rms_m, 1e-9);
}

// Smoothing trades closeness for smoothness: a larger weight moves the spline away from noisy poses.
TEST(RecordedTrajectory, SmoothingDampsNoisyPoses) {
  std::vector<TimedPose> poses;
  for (int k = 0; k <= 100; ++k) {
    const double jitter = (k % 2 ? 1.0 : -1.0) * 2e-3;  // 2 mm alternating "ground-truth noise"
    poses.push_back(
        {50'000'000LL * k, Eigen::Vector3d(0.05 * k + jitter, 0, 1), Eigen::Quaterniond::Identity()});
  }
  RecordedTrajectoryOptions none, strong;
  none.smoothing = 0.0;
  strong.smoothing = 1.0;
  const RecordedTrajectory a(poses, none), b(poses, strong);
  double peak_a = 0, peak_b = 0;
  for (double t = 0.5; t < 4.5; t += 0.01) {
    peak_a = std::max(peak_a, a.StateAt(t).a_W.norm());
    peak_b = std::max(peak_b, b.StateAt(t).a_W.norm());
  }
  EXPECT_GT(peak_a, 3.0);  // the alternating 2 mm at 20 Hz is several m/s^2 when followed
  EXPECT_LT(peak_b, 0.3 * peak_a);
  EXPECT_GT(b.Fit().position_rms_m, a.Fit().position_rms_m);
}

TEST(RecordedPoses, ReadsTheEurocExcerptAndFitsIt) {
  const std::vector<TimedPose> poses = ReadRecordedPoses(kExcerpt);
  ASSERT_EQ(poses.size(), 120u);
  EXPECT_EQ(poses.front().t_ns, 1403715283262142976);
  ASSERT_TRUE(poses.front().v_W.has_value());
  const RecordedTrajectory m(poses, RecordedTrajectoryOptions{});
  const FitReport r = m.Fit();
  std::printf("V1_01 excerpt (6 s): position rms %.3g m, rotation rms %.3g deg, velocity rms %.3g m/s\n",
              r.position_rms_m, r.rotation_rms_deg, r.velocity_rms_mps);
  EXPECT_NEAR(r.knot_spacing_s, 0.05, 1e-6);
  EXPECT_LT(r.position_rms_m, 2e-3);
  EXPECT_LT(r.rotation_rms_deg, 0.2);
  EXPECT_LT(r.velocity_rms_mps, 0.05);
  ExpectDerivativesMatchFiniteDifferences(m, 0.0, m.EndTime(), 2e-5);
}

TEST(RecordedPoses, ReadsTumAndEurocFolders) {
  TempDir tmp;
  const std::string tum = tmp.File("traj.txt",
                                   "# timestamp tx ty tz qx qy qz qw\n"
                                   "10.0 1 2 3 0 0 0 1\n"
                                   "10.1 1.1 2 3 0 0 0.0499792 0.9987503\n"
                                   "\n"
                                   "10.2 1.2 2 3 0 0 0.0998334 0.9950042\n");
  const std::vector<TimedPose> poses = ReadRecordedPoses(tum);
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_EQ(poses[1].t_ns, 10'100'000'000);
  EXPECT_FALSE(poses[1].v_W.has_value());
  EXPECT_NEAR(AngleOf(poses[2].q_WB), 0.2, 1e-6);
  // The folder holding mav0/, and mav0/ itself.
  const fs::path gt = tmp.path() / "seq/mav0/state_groundtruth_estimate0";
  fs::create_directories(gt);
  fs::copy_file(kExcerpt, gt / "data.csv");
  EXPECT_EQ(ReadRecordedPoses(tmp.path() / "seq").size(), 120u);
  EXPECT_EQ(ReadRecordedPoses(tmp.path() / "seq/mav0").size(), 120u);
  EXPECT_NE(InputErrorOf([&] { ReadRecordedPoses(tmp.path()); }).find("no ground truth found"),
            std::string::npos);
}

TEST(RecordedPoses, RefusesBadRecordings) {
  TempDir tmp;
  const std::string header = "#time(ns),px,py,pz,qw,qx,qy,qz,vx,vy,vz,bwx,bwy,bwz,bax,bay,baz\n";
  const std::string tail = ",0,0,0,0,0,0,0,0,0\n";
  const auto euroc = [&](const std::string& rows) { return tmp.File("gt.csv", header + rows); };
  const auto error = [&](const std::string& path) { return InputErrorOf([&] { ReadRecordedPoses(path); }); };
  EXPECT_EQ(error(euroc("100,0,0,0,1,0,0,0" + tail)),
            tmp.path().string() + "/gt.csv:2: 1 pose(s): a recorded trajectory needs at least 2");
  EXPECT_EQ(error(euroc("100,0,0,0,1,0,0,0" + tail + "90,0,0,0,1,0,0,0" + tail)),
            tmp.path().string() + "/gt.csv:3: timestamp 90 ns does not increase (previous 100 ns)");
  EXPECT_NE(error(euroc("100,0,0,0,1,0,0,0" + tail + "100,0,0,0,1,0,0,0" + tail))
                .find(":3: timestamp 100 ns does not increase"),
            std::string::npos);
  EXPECT_NE(error(euroc("100,0,0,0,1,0,0,0" + tail + "200,nan,0,0,1,0,0,0" + tail))
                .find(":3: px: expected a finite number"),
            std::string::npos);
  EXPECT_NE(error(euroc("100,0,0,0,1,0,0,0" + tail + "200,0,0,0,0.9,0,0,0" + tail))
                .find(":3: quaternion is not unit (norm 0.9)"),
            std::string::npos);
  EXPECT_NE(error(euroc("100000000,0,0,0,1,0,0,0" + tail + "150000000,8,0,0,1,0,0,0" + tail))
                .find(":3: position jumps 8 m"),
            std::string::npos);
  EXPECT_NE(error(euroc("100000000,0,0,0,1,0,0,0" + tail + "150000000,0,0,0,0,1,0,0" + tail))
                .find(":3: orientation jumps 180 deg"),
            std::string::npos);
  EXPECT_NE(error(tmp.File("short.csv", "#t,x,y,z,qw,qx,qy,qz\n1,0,0,0,1,0,0,0\n"))
                .find(":1: header has 8 columns, expected 17 or more"),
            std::string::npos);
  EXPECT_NE(error(tmp.File("t.txt", "1 0 0 0 0 0 0 1\n2 0 0 0 0 0 1\n")).find("t.txt:2: expected 8 columns"),
            std::string::npos);
}

TEST(RecordedTrajectory, IsBuiltFromTheTrajectoryOptions) {
  TrajectoryOptions o;
  o.type = TrajectoryType::kRecording;
  EXPECT_EQ(InputErrorOf([&] { MakeTrajectoryModel(o); }),
            "trajectory.recording: required for trajectory.type recording");
  o.recording = kExcerpt.string();
  const std::unique_ptr<TrajectoryModel> m = MakeTrajectoryModel(o);
  EXPECT_NEAR(m->EndTime(), 5.95, 1e-6);
  EXPECT_LT((m->StateAt(0.0).p_W - Eigen::Vector3d(1.75378, 2.49389, 1.11927)).norm(), 2e-3);
  o.recording = "/nonexistent/gt.csv";
  EXPECT_EQ(
      InputErrorOf([&] { MakeTrajectoryModel(o); }).rfind("trajectory.recording: /nonexistent/gt.csv", 0),
      0u);
}

// The sizes a config value drives are checked before anything is allocated: a knot spacing of 1 ns over a
// second would be a billion control points (it grew to GBs before bad_alloc), and a duration beyond the
// recording is refused before the spline is fitted.
TEST(RecordedTrajectory, KnotCountAndDurationAreCheckedBeforeTheFit) {
  TempDir tmp;
  TrajectoryOptions o;
  o.type = TrajectoryType::kRecording;
  o.recording = tmp.File("traj.txt", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n");
  o.spline.knot_spacing_s = 1e-9;
  EXPECT_EQ(InputErrorOf([&] { MakeTrajectoryModel(o, 5.0); }),
            "duration_s: 5 s exceeds the end of the trajectory (1 s)");
  EXPECT_EQ(
      InputErrorOf([&] { MakeTrajectoryModel(o, 1.0); }),
      "trajectory.spline.knot_spacing_s: 1e-09 s over the recording's 1 s needs 1000000003 spline control "
      "points, more than the limit of 100000; set a larger spacing, at least " +
          FormatDouble(1.0 / 99997) + " s");
  o.spline.knot_spacing_s = 1e-3;
  EXPECT_EQ(MakeTrajectoryModel(o, 1.0)->EndTime(), 1.0);
  EXPECT_EQ(SplineControlPoints(1.0, 1e-3), 1003.0);
}

// A recorded ground truth with a gap: a spline through it would invent the motion, so the gap is refused at
// its row (the same bound as the dataset readers').
TEST(RecordedPoses, RefusesAGapLongerThanASecond) {
  TempDir tmp;
  const std::string tum = tmp.File("traj.txt", "0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n301 1 0 0 0 0 0 1\n");
  EXPECT_EQ(
      InputErrorOf([&] { ReadRecordedPoses(tum); }),
      tum +
          ":3: no pose for 300 s since the previous row (more than the limit of 1 s): the motion across "
          "the gap is unknown; split the recording there");
  EXPECT_EQ(ReadRecordedPoses(tmp.File("ok.txt", "0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n")).size(), 2u);
}

// duration_s: 0 is "to the end of the recording", resolved from the recording's timestamps; motions without
// an end keep 0, which the validation refuses naming the key.
TEST(RecordedTrajectory, DurationZeroRunsToTheEndOfTheRecording) {
  SimOptions o;
  o.duration_s = 0.0;
  o.trajectory.type = TrajectoryType::kRecording;
  o.trajectory.recording = kExcerpt.string();
  ResolveDurationToEnd(&o);
  EXPECT_EQ(o.duration_s, 5.949999872);  // the timestamps of the first and last rows
  EXPECT_EQ(InputErrorOf([&] { ValidateSimOptions(o, "c.yaml"); }), "");
  o.duration_s = 3.0;
  ResolveDurationToEnd(&o);
  EXPECT_EQ(o.duration_s, 3.0);
  o.duration_s = 0.0;
  o.trajectory.type = TrajectoryType::kEllipse;
  ResolveDurationToEnd(&o);
  EXPECT_EQ(o.duration_s, 0.0);
  EXPECT_EQ(InputErrorOf([&] { ValidateSimOptions(o, "c.yaml"); }),
            "c.yaml: duration_s: must be at least 0.5 s, got 0 s (0, to the end of the trajectory, needs "
            "trajectory.type waypoints or recording)");
  // An explicit value too short is only that; 0 on a recording shorter than a run is said as such (the
  // type the config already has is not asked for).
  o.trajectory.type = TrajectoryType::kRecording;
  o.duration_s = 0.2;
  EXPECT_EQ(InputErrorOf([&] { ValidateSimOptions(o, "c.yaml"); }),
            "c.yaml: duration_s: must be at least 0.5 s, got 0.2 s");
  TempDir tmp;
  o.trajectory.recording = tmp.File("short.txt", "0 0 0 0 0 0 0 1\n0.3 1 0 0 0 0 0 1\n");
  o.duration_s = 0.0;
  EXPECT_EQ(InputErrorOf([&] { ResolveDurationToEnd(&o); }),
            "duration_s: 0 runs to the end of trajectory.recording, which is 0.300 s long: a run needs at "
            "least 0.5 s");
}

// The whole V1_01 ground truth (2,895 poses at 20 Hz, 145 s; roll near +-pi throughout). Measured: position
// rms 1.1e-5 m (max 7.6e-5), rotation rms 0.0059 deg (max 0.025), velocity rms 4.6 mm/s (max 0.05 m/s)
// against EuRoC's own velocities, which the fit never sees.
TEST(RecordedTrajectoryEuroc, FitsTheWholeV1_01GroundTruth) {
  if (!fs::exists(kEuroc)) GTEST_SKIP() << "SKIPPED: " << kEuroc.string() << " is absent";
  const RecordedTrajectory m(ReadRecordedPoses(kEuroc), RecordedTrajectoryOptions{});
  const FitReport r = m.Fit();
  std::printf(
      "V1_01 fit: %zu poses, %zu control points, knots %.4g s: position rms %.3g m (max %.3g), rotation rms "
      "%.3g "
      "deg (max %.3g), velocity rms %.3g m/s (max %.3g)\n",
      r.poses, r.control_points, r.knot_spacing_s, r.position_rms_m, r.position_max_m, r.rotation_rms_deg,
      r.rotation_max_deg, r.velocity_rms_mps, r.velocity_max_mps);
  EXPECT_EQ(r.poses, 2895u);
  EXPECT_NEAR(m.EndTime(), 144.7, 0.01);
  EXPECT_LT(r.position_rms_m, 5e-5);
  EXPECT_LT(r.rotation_rms_deg, 0.02);
  EXPECT_LT(r.velocity_rms_mps, 0.01);
}

// An ideal IMU simulated along the recorded trajectory integrates back to it: the midpoint rule's error over
// the 145 s is O(dt^2) (it shrinks 4x from 200 to 400 Hz), so the IMU and the trajectory agree to the
// integrator's truncation. Measured rms: 200 Hz 0.114 m, 2.5 mm/s, 3.3e-4 deg; 400 Hz 0.0285 m, 0.62 mm/s,
// 8.3e-5 deg (the tilt error of the gyro integration, 5e-6 rad, turns gravity into drift over 145 s).
TEST(RecordedTrajectoryEuroc, IdealImuIntegratesBackToTheRecording) {
  if (!fs::exists(kEuroc)) GTEST_SKIP() << "SKIPPED: " << kEuroc.string() << " is absent";
  const RecordedTrajectory m(ReadRecordedPoses(kEuroc), RecordedTrajectoryOptions{});
  ImuOptions imu;
  imu.noise.enabled = false;
  imu.rate_hz = 200.0;
  const IntegrationError e200 = IntegrateMidpoint(SynthesizeImu(m, imu, m.EndTime(), 9.81, 1), 9.81);
  imu.rate_hz = 400.0;
  const IntegrationError e400 = IntegrateMidpoint(SynthesizeImu(m, imu, m.EndTime(), 9.81, 1), 9.81);
  std::printf(
      "V1_01 ideal IMU, midpoint over %.1f s: 200 Hz rms p %.3g m (max %.3g) v %.3g m/s R %.3g deg; "
      "400 Hz rms p %.3g m v %.3g m/s R %.3g deg\n",
      m.EndTime(), e200.p_rms_m, e200.p_m, e200.v_rms_mps, e200.rot_rms_deg, e400.p_rms_m, e400.v_rms_mps,
      e400.rot_rms_deg);
  EXPECT_LT(e200.p_rms_m, 0.25);
  EXPECT_LT(e200.v_rms_mps, 0.006);
  EXPECT_LT(e200.rot_rms_deg, 1e-3);
  EXPECT_NEAR(e200.p_rms_m / e400.p_rms_m, 4.0, 0.6);
  EXPECT_NEAR(e200.v_rms_mps / e400.v_rms_mps, 4.0, 0.6);
  EXPECT_NEAR(e200.rot_rms_deg / e400.rot_rms_deg, 4.0, 0.6);
}

}  // namespace
}  // namespace vigil::sim
