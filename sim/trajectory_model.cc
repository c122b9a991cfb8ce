#include "sim/trajectory_model.h"

#include "core/error.h"
#include "sim/ellipse_trajectory.h"
#include "sim/rescue_trajectory.h"
#include "sim/waypoint_trajectory.h"

namespace vigil::sim {

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
  }
  throw InputError("trajectory.type: unknown motion model");
}

}  // namespace vigil::sim
