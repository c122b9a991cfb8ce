// A trajectory that follows a recorded ground truth (trajectory.type recording).
//
// The recorded poses (sim/recorded_poses.h) are fitted by a cumulative cubic B-spline on SO(3) x R^3
// (sim/cumulative_bspline.h, sim/spline_fit.h) with uniform knots: knot_spacing_s apart (default: the
// recording's median pose spacing). The spline's analytic derivatives give v_W, a_W and w_B, so an IMU
// synthesized along it integrates back to the spline exactly up to the integrator's error; the spline itself
// passes near, not through, the poses: Fit() reports how near. Time t_s = 0 is the first recorded pose
// (StartNs()); the model ends at the last one. Quaternions throughout: no Euler angles, so any attitude
// (EuRoC's body flies with roll near +-pi) is represented without wrapping.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "sim/cumulative_bspline.h"
#include "sim/recorded_poses.h"
#include "sim/sim_options.h"
#include "sim/trajectory_model.h"

namespace vigil::sim {

// The most control points a fitted spline may have: the fit's memory and time grow with them (199,003
// control points took 1.1 GB and 106 s), so trajectory.spline.knot_spacing_s (or a recording's own span and
// median pose spacing) is checked against this before anything is allocated. 100,000 is over 8 minutes of
// a 200 Hz ground truth at its own spacing (EuRoC's longest sequence is 3 minutes).
inline constexpr double kMaxSplineControlPoints = 100000;

// The control points a spline with knots `dt_s` apart over `span_s` seconds has (segments + 3).
double SplineControlPoints(double span_s, double dt_s);

// How far the fitted spline is from the recording, over all recorded poses.
struct FitReport {
  std::size_t poses = 0;
  std::size_t control_points = 0;
  double knot_spacing_s = 0.0;
  double position_rms_m = 0.0, position_max_m = 0.0;
  double rotation_rms_deg = 0.0, rotation_max_deg = 0.0;
  bool has_velocity = false;  // the recording has velocities (EuRoC ground truth)
  double velocity_rms_mps = 0.0, velocity_max_mps = 0.0;
};

// The kinematic state a spline sample stands for.
TrajectoryState StateOf(const CumulativeBSpline::Sample& sample);

class RecordedTrajectory final : public TrajectoryModel {
 public:
  // At least 2 poses with increasing times (InputError otherwise).
  RecordedTrajectory(std::vector<TimedPose> poses, const RecordedTrajectoryOptions& options);

  TrajectoryState StateAt(double t_s) const override;
  double EndTime() const override { return end_time_s_; }
  // Absolute time of t_s = 0 (the first recorded pose) [ns].
  int64_t StartNs() const { return poses_.front().t_ns; }
  FitReport Fit() const;

  const CumulativeBSpline& spline() const { return spline_; }
  const std::vector<TimedPose>& poses() const { return poses_; }

 private:
  std::vector<TimedPose> poses_;
  double end_time_s_ = 0.0;
  CumulativeBSpline spline_;
};

// The median spacing of the poses' timestamps [s].
double MedianPoseSpacing(const std::vector<TimedPose>& poses);

}  // namespace vigil::sim
