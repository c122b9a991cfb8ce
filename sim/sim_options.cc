#include "sim/sim_options.h"

#include "core/error.h"

namespace vigil::sim {

void ValidateSimOptions(const SimOptions& options, const std::string& origin) {
  const std::string camera = options.camera.Validate();
  if (!camera.empty()) throw InputError(origin + ": camera." + camera);
  if (options.glitch.enabled && options.glitch.axes.empty())
    throw InputError(origin + ": glitch.axes: must name at least one axis when glitch.enabled is true");
  if (options.imu.rate_hz < options.camera.rate_hz)
    throw InputError(origin + ": imu.rate_hz: must be at least camera.rate_hz");
  if (options.imu.rate_hz > 1e6) throw InputError(origin + ": imu.rate_hz: must be at most 1e6");
  if (options.landmarks.layout != LandmarkLayout::kHouse && options.landmarks.random_count <= 0)
    throw InputError(origin +
                     ": landmarks.random_count: must be > 0 for the layouts random and house+random");
  if (options.trajectory.type == TrajectoryType::kWaypoints && options.trajectory.waypoints_file.empty())
    throw InputError(origin + ": trajectory.waypoints_file: required for trajectory.type waypoints");
}

}  // namespace vigil::sim
