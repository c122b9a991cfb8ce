#include "sim/trajectory_model.h"

#include "core/data_dir.h"
#include "core/error.h"
#include "core/format.h"
#include "core/types.h"
#include "sim/ellipse_trajectory.h"
#include "sim/recorded_trajectory.h"
#include "sim/rescue_trajectory.h"
#include "sim/waypoint_trajectory.h"

namespace vigil::sim {
namespace {

std::string DurationBeyondEnd(double duration_s, double end_s) {
  return "duration_s: " + FormatDouble(duration_s) + " s exceeds the end of the trajectory (" +
         FormatDouble(end_s) + " s)";
}

// The model of `options.type`; a recording is read and its span checked against `duration_s` before its
// spline is fitted.
std::unique_ptr<TrajectoryModel> MakeModel(const TrajectoryOptions& options, double duration_s) {
  switch (options.type) {
    case TrajectoryType::kEllipse:
      return std::make_unique<EllipseTrajectory>();
    case TrajectoryType::kRescue:
      return std::make_unique<RescueTrajectory>();
    case TrajectoryType::kWaypoints:
      if (options.waypoints_file.empty())
        throw InputError("trajectory.waypoints_file: required for trajectory.type waypoints");
      try {
        return std::make_unique<WaypointTrajectory>(ReadWaypoints(options.waypoints_file));
      } catch (const InputError& e) {
        throw InputError(std::string("trajectory.waypoints_file: ") + e.what());
      }
    case TrajectoryType::kRecording: {
      if (options.recording.empty())
        throw InputError("trajectory.recording: required for trajectory.type recording");
      std::vector<TimedPose> poses;
      try {
        poses = ReadRecordedPoses(options.recording);
      } catch (const InputError& e) {
        throw InputError(std::string("trajectory.recording: ") + e.what());
      }
      const double span_s = static_cast<double>(poses.back().t_ns - poses.front().t_ns) / 1e9;
      if (duration_s > span_s) throw InputError(DurationBeyondEnd(duration_s, span_s));
      return std::make_unique<RecordedTrajectory>(std::move(poses), options.spline);
    }
  }
  throw InputError("trajectory.type: unknown motion model");
}

}  // namespace

void ResolveDurationToEnd(SimOptions* options) {
  const TrajectoryOptions& t = options->trajectory;
  // An unset $VIGIL_DATA: nothing to read, ValidateSimOptions says why.
  if (options->duration_s != 0.0 || NamesDataDir(t.waypoints_file) || NamesDataDir(t.recording)) return;
  try {
    if (t.type == TrajectoryType::kWaypoints && !t.waypoints_file.empty()) {
      const std::vector<Waypoint> w = ReadWaypoints(t.waypoints_file);
      options->duration_s = w.back().t_s - w.front().t_s;
    }
  } catch (const InputError& e) {
    throw InputError(std::string("trajectory.waypoints_file: ") + e.what());
  }
  try {
    if (t.type == TrajectoryType::kRecording && !t.recording.empty()) {
      const std::vector<TimedPose> poses = ReadRecordedPoses(t.recording);
      options->duration_s = static_cast<double>(poses.back().t_ns - poses.front().t_ns) / 1e9;
    }
  } catch (const InputError& e) {
    throw InputError(std::string("trajectory.recording: ") + e.what());
  }
  if (options->duration_s != 0.0 && options->duration_s < kMinDuration_s)
    throw InputError("duration_s: 0 runs to the end of trajectory." +
                     std::string(t.type == TrajectoryType::kWaypoints ? "waypoints_file" : "recording") +
                     ", which is " + FormatPrintf("%.3f", options->duration_s) +
                     " s long: a run needs at least " + FormatDouble(kMinDuration_s) + " s");
}

std::unique_ptr<TrajectoryModel> MakeTrajectoryModel(const TrajectoryOptions& options, double duration_s) {
  std::unique_ptr<TrajectoryModel> motion = MakeModel(options, duration_s);
  if (duration_s > motion->EndTime()) throw InputError(DurationBeyondEnd(duration_s, motion->EndTime()));
  return motion;
}

}  // namespace vigil::sim
