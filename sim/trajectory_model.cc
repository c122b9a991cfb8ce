#include "sim/trajectory_model.h"

#include "sim/ellipse_trajectory.h"

namespace vigil::sim {

std::unique_ptr<TrajectoryModel> MakeTrajectoryModel(const TrajectoryOptions& options) {
  switch (options.type) {
    case TrajectoryType::kEllipse:
      return std::make_unique<EllipseTrajectory>();
    case TrajectoryType::kRescue:
    case TrajectoryType::kWaypoints:
      break;
  }
  throw InputError("trajectory.type: not available yet");
}

}  // namespace vigil::sim
