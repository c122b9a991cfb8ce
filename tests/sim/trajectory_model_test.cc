#include "sim/trajectory_model.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/so3.h"
#include "sim/ellipse_trajectory.h"
#include "sim/rescue_trajectory.h"
#include "sim/waypoint_trajectory.h"
#include "tests/core/test_util.h"

namespace vigil::sim {
namespace {

// Checks the model's exact derivatives against central differences of the model itself (the test may use
// finite differences; the models may not). Central differences err by h^2 / 6 times the next derivative
// (below 1e-7 here with h = 2e-5 s, even over the rescue course's bumps) plus rounding, about 1e-16 |x| / h.
// The rescue course is only C2 (jerk jumps where its smoothsteps start and end); the sample times below stay
// clear of those instants.
void ExpectDerivativesConsistent(const TrajectoryModel& model, double t_end, double tol) {
  const double h = 2e-5;
  for (double t = 0.01; t < t_end - h; t += 0.0137 * t_end) {
    const TrajectoryState x = model.StateAt(t), xm = model.StateAt(t - h), xp = model.StateAt(t + h);
    EXPECT_LT((x.v_W - (xp.p_W - xm.p_W) / (2 * h)).norm(), tol) << "velocity at t = " << t;
    EXPECT_LT((x.a_W - (xp.v_W - xm.v_W) / (2 * h)).norm(), tol) << "acceleration at t = " << t;
    // Body rate: R(t + h) = R(t - h) Exp(w_B 2h) to second order in h.
    const Eigen::Vector3d w_fd = LogQ(xm.q_WB.conjugate() * xp.q_WB) / (2 * h);
    EXPECT_LT((x.w_B - w_fd).norm(), tol) << "body rate at t = " << t;
    EXPECT_NEAR(x.q_WB.norm(), 1.0, 1e-12);
  }
}

TEST(EllipseTrajectory, MatchesTheReferenceAtTimeZero) {
  const EllipseTrajectory e;
  const TrajectoryState x = e.StateAt(0.0);
  constexpr double K = EllipseTrajectory::kK;
  EXPECT_LT((x.p_W - Eigen::Vector3d(20, 5, 5)).norm(), 1e-12);
  EXPECT_LT((x.v_W - Eigen::Vector3d(0, 20 * K, 10 * K)).norm(), 1e-12);
  EXPECT_LT((x.a_W - Eigen::Vector3d(-15 * K * K, 0, 0)).norm(), 1e-12);
  // roll = 0.1, pitch = yaw = 0 at t = 0; Euler rates (0, 0.2, K) -> w_B = E (0, 0.2, K).
  EXPECT_NEAR(AngleOf(x.q_WB), 0.1, 1e-12);
  const Eigen::Vector3d w(0.0, std::cos(0.1) * 0.2 + std::sin(0.1) * K,
                          -std::sin(0.1) * 0.2 + std::cos(0.1) * K);
  EXPECT_LT((x.w_B - w).norm(), 1e-12);
  // One loop every 20 s.
  EXPECT_LT((e.StateAt(20.0).p_W - x.p_W).norm(), 1e-9);
}

TEST(EllipseTrajectory, DerivativesAreExact) { ExpectDerivativesConsistent(EllipseTrajectory(), 20.0, 1e-6); }

TEST(RescueTrajectory, DerivativesAreExact) { ExpectDerivativesConsistent(RescueTrajectory(), 36.0, 1e-6); }

TEST(RescueTrajectory, DrivesAClosedCourseOnTheGround) {
  const RescueTrajectory course;
  const double period = RescueTrajectory::kLoopPeriodS;
  double length = 0, speed_min = 1e9, speed_max = 0, z_max = 0;
  Eigen::Vector3d last = course.StateAt(0.0).p_W;
  for (double t = 0.0; t <= period; t += 0.005) {
    const TrajectoryState x = course.StateAt(t);
    length += (x.p_W - last).norm();
    last = x.p_W;
    speed_min = std::min(speed_min, x.v_W.norm());
    speed_max = std::max(speed_max, x.v_W.norm());
    z_max = std::max(z_max, x.p_W.z());
    EXPECT_GE(x.p_W.z(), RescueTrajectory::kBodyHeightM - 1e-12);
    // x_B points along the horizontal velocity.
    const Eigen::Vector3d x_B = x.q_WB * Eigen::Vector3d::UnitX();
    const Eigen::Vector2d heading = x.v_W.head<2>().normalized();
    EXPECT_NEAR(x_B.head<2>().normalized().dot(heading), 1.0, 1e-9);
  }
  EXPECT_NEAR(length / period, 1.0, 0.05);  // about 1 m/s on average
  EXPECT_GT(speed_min, 0.6);
  EXPECT_LT(speed_max, 1.6);
  EXPECT_NEAR(z_max, RescueTrajectory::kBodyHeightM + 0.4, 0.05);
  // The loop closes: same pose and velocity one period later.
  const TrajectoryState a = course.StateAt(1.0), b = course.StateAt(1.0 + period);
  EXPECT_LT((a.p_W - b.p_W).norm(), 1e-9);
  EXPECT_LT((a.v_W - b.v_W).norm(), 1e-9);
  EXPECT_LT(AngleOf(a.q_WB.conjugate() * b.q_WB), 1e-9);
}

// Steps and bumps are real, short vertical acceleration peaks of a few m/s^2 (what a detector must accept).
TEST(RescueTrajectory, StepsAndBumpsGiveShortAccelerationPeaks) {
  const RescueTrajectory course;
  int peaks = 0;
  double peak_max = 0, above_duration = 0, longest = 0;
  bool in_peak = false;
  for (double t = 0.0; t <= RescueTrajectory::kLoopPeriodS; t += 0.001) {
    const double a_z = std::abs(course.StateAt(t).a_W.z());
    peak_max = std::max(peak_max, a_z);
    if (a_z > 1.0) {
      if (!in_peak) ++peaks;
      in_peak = true;
      above_duration += 0.001;
      longest = std::max(longest, above_duration);
    } else {
      in_peak = false;
      above_duration = 0;
    }
  }
  EXPECT_GE(peaks, 5);       // two steps and three bumps (each with several lobes)
  EXPECT_GT(peak_max, 2.0);  // a few m/s^2 ...
  EXPECT_LT(peak_max, 6.0);
  EXPECT_LT(longest, 0.2);  // ... lasting tens of milliseconds
}

std::string WaypointFile(const testing::TempDir& tmp, const std::string& rows) {
  return tmp.File("wp.csv", "#t [s],x [m],y [m],z [m],yaw [rad],pitch [rad],roll [rad]\n" + rows);
}

TEST(WaypointTrajectory, PassesThroughEveryWaypointWithExactDerivatives) {
  testing::TempDir tmp;
  const auto waypoints = ReadWaypoints(WaypointFile(tmp,
                                                    "10,0,0,1,0,0,0\n"
                                                    "11,1,0.5,1.2,0.3,0.05,-0.02\n"
                                                    "12.5,2,2,1.1,3.0,0.1,0.03\n"  // yaw 3.0 then -3.0:
                                                    "14,1,3,0.9,-3.0,0.0,0.0\n"    // the short way round
                                                    "16,-1,2,1,-2.5,-0.05,0.01\n"));
  const WaypointTrajectory model(waypoints);
  EXPECT_EQ(model.EndTime(), 6.0);  // time starts at the first waypoint
  for (const Waypoint& w : waypoints) {
    const TrajectoryState x = model.StateAt(w.t_s - 10.0);
    EXPECT_LT((x.p_W - w.p_W).norm(), 1e-12);
    const Eigen::Matrix3d R = x.q_WB.toRotationMatrix();
    EXPECT_NEAR(YawOf(R), w.yaw, 1e-12);
    EXPECT_NEAR(-std::asin(R(2, 0)), w.pitch, 1e-12);
  }
  // Between yaw 3.0 and -3.0 the heading passes through pi, not through 0.
  EXPECT_GT(std::abs(YawOf(model.StateAt(3.25).q_WB.toRotationMatrix())), 2.5);
  ExpectDerivativesConsistent(model, 6.0, 1e-6);
  EXPECT_LT(model.StateAt(0.0).a_W.norm(), 1e-12);  // natural spline: no acceleration at the ends
}

TEST(WaypointTrajectory, BadFilesAreRejectedWithFileAndLine) {
  testing::TempDir tmp;
  using testing::InputErrorOf;
  const std::string unordered = WaypointFile(tmp, "0,0,0,0,0,0,0\n1,1,0,0,0,0,0\n1,2,0,0,0,0,0\n");
  EXPECT_EQ(InputErrorOf([&] { ReadWaypoints(unordered); }), unordered + ":4: time does not increase");
  const std::string one = WaypointFile(tmp, "0,0,0,0,0,0,0\n");
  EXPECT_NE(InputErrorOf([&] { ReadWaypoints(one); }).find("at least 2 waypoints"), std::string::npos);
  const std::string text = WaypointFile(tmp, "0,0,0,0,0,0,0\n1,1,zero,0,0,0,0\n");
  EXPECT_NE(InputErrorOf([&] { ReadWaypoints(text); }).find(":3: "), std::string::npos);
  TrajectoryOptions o;
  o.type = TrajectoryType::kWaypoints;
  o.waypoints_file = (tmp.path() / "missing.csv").string();
  EXPECT_EQ(InputErrorOf([&] { MakeTrajectoryModel(o); }).rfind("trajectory.waypoints_file: ", 0), 0u);
}

}  // namespace
}  // namespace vigil::sim
