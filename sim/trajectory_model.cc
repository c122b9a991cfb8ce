#include "sim/trajectory_model.h"

#include "core/data_dir.h"
#include "core/error.h"
#include "sim/ellipse_trajectory.h"
#include "sim/recorded_trajectory.h"
#include "sim/rescue_trajectory.h"
#include "sim/waypoint_trajectory.h"

namespace vigil::sim {

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
}

std::unique_ptr<TrajectoryModel> MakeTrajectoryModel(const TrajectoryOptions& options) {
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
    case TrajectoryType::kRecording:
      if (options.recording.empty())
        throw InputError("trajectory.recording: required for trajectory.type recording");
      try {
        return std::make_unique<RecordedTrajectory>(ReadRecordedPoses(options.recording), options.spline);
      } catch (const InputError& e) {
        throw InputError(std::string("trajectory.recording: ") + e.what());
      }
  }
  throw InputError("trajectory.type: unknown motion model");
}

}  // namespace vigil::sim
