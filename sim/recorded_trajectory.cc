#include "sim/recorded_trajectory.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/format.h"
#include "core/so3.h"
#include "core/types.h"
#include "sim/spline_fit.h"

namespace vigil::sim {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

const std::vector<TimedPose>& Checked(const std::vector<TimedPose>& poses) {
  if (poses.size() < 2)
    throw InputError("a recorded trajectory needs at least 2 poses, found " + std::to_string(poses.size()));
  for (std::size_t k = 1; k < poses.size(); ++k)
    if (poses[k].t_ns <= poses[k - 1].t_ns)
      throw InputError("recorded pose " + std::to_string(k) + ": timestamp does not increase");
  return poses;
}

CumulativeBSpline Fitted(const std::vector<TimedPose>& poses, const RecordedTrajectoryOptions& options) {
  const double span_s = static_cast<double>(poses.back().t_ns - poses.front().t_ns) / 1e9;
  const double dt_s = options.knot_spacing_s > 0.0 ? options.knot_spacing_s : MedianPoseSpacing(poses);
  const double control_points = SplineControlPoints(span_s, dt_s);
  if (!(control_points <= kMaxSplineControlPoints))
    throw InputError(
        "trajectory.spline.knot_spacing_s: " +
        (options.knot_spacing_s > 0.0
             ? FormatDouble(dt_s) + " s"
             : "0 (the recording's median pose spacing, " + FormatDouble(dt_s) + " s)") +
        " over the recording's " + FormatDouble(span_s) + " s needs " + FormatPrintf("%.0f", control_points) +
        " spline control points, more than the limit of " + FormatPrintf("%.0f", kMaxSplineControlPoints) +
        "; set a larger spacing, at least " + FormatDouble(span_s / (kMaxSplineControlPoints - 3)) + " s");
  std::vector<SplineFitPose> samples;
  samples.reserve(poses.size());
  for (const TimedPose& p : poses) samples.push_back({NsToS(p.t_ns - poses.front().t_ns), p.p_W, p.q_WB});
  return FitCumulativeBSpline(samples, dt_s, options.smoothing);
}

}  // namespace

double SplineControlPoints(double span_s, double dt_s) {
  return std::max(1.0, std::ceil(span_s / dt_s - 1e-9)) + 3.0;  // as FitCumulativeBSpline lays them out
}

double MedianPoseSpacing(const std::vector<TimedPose>& poses) {
  std::vector<int64_t> gaps;
  for (std::size_t k = 1; k < poses.size(); ++k) gaps.push_back(poses[k].t_ns - poses[k - 1].t_ns);
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
  return NsToS(gaps[gaps.size() / 2]);
}

RecordedTrajectory::RecordedTrajectory(std::vector<TimedPose> poses, const RecordedTrajectoryOptions& options)
    : poses_(std::move(poses)),
      end_time_s_(static_cast<double>(Checked(poses_).back().t_ns - poses_.front().t_ns) / 1e9),
      spline_(Fitted(poses_, options)) {}

TrajectoryState StateOf(const CumulativeBSpline::Sample& sample) {
  TrajectoryState x;
  x.p_W = sample.p_W;
  x.v_W = sample.v_W;
  x.a_W = sample.a_W;
  x.q_WB = sample.q_WB;
  x.w_B = sample.w_B;
  return x;
}

TrajectoryState RecordedTrajectory::StateAt(double t_s) const { return StateOf(spline_.Evaluate(t_s)); }

FitReport RecordedTrajectory::Fit() const {
  FitReport r;
  r.poses = poses_.size();
  r.control_points = spline_.control_points().size();
  r.knot_spacing_s = spline_.dt_s();
  double ss_p = 0, ss_r = 0, ss_v = 0;
  std::size_t n_v = 0;
  for (const TimedPose& p : poses_) {
    const TrajectoryState x = StateAt(NsToS(p.t_ns - StartNs()));
    const double e_p = (x.p_W - p.p_W).norm();
    const double e_r = AngleOf(p.q_WB.conjugate() * x.q_WB) * kRadToDeg;
    ss_p += e_p * e_p;
    ss_r += e_r * e_r;
    r.position_max_m = std::max(r.position_max_m, e_p);
    r.rotation_max_deg = std::max(r.rotation_max_deg, e_r);
    if (p.v_W) {
      const double e_v = (x.v_W - *p.v_W).norm();
      ss_v += e_v * e_v;
      ++n_v;
      r.velocity_max_mps = std::max(r.velocity_max_mps, e_v);
    }
  }
  const double n = static_cast<double>(poses_.size());
  r.position_rms_m = std::sqrt(ss_p / n);
  r.rotation_rms_deg = std::sqrt(ss_r / n);
  r.has_velocity = n_v > 0;
  if (n_v > 0) r.velocity_rms_mps = std::sqrt(ss_v / static_cast<double>(n_v));
  return r;
}

}  // namespace vigil::sim
