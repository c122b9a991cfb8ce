#include "sim/sim_options.h"

#include "core/data_dir.h"
#include "core/error.h"
#include "core/format.h"

namespace vigil::sim {

void ResolveRelativePaths(const std::filesystem::path& base_dir, SimOptions* options) {
  for (std::string* file :
       {&options->trajectory.waypoints_file, &options->trajectory.recording, &options->imu.recording})
    *file = ResolveInputPath(base_dir, *file);  // "$VIGIL_DATA" while unset: ValidateSimOptions says so
}

void ValidateSimOptions(const SimOptions& options, const std::string& origin) {
  for (const auto& [key, file] : {std::pair{"trajectory.waypoints_file", &options.trajectory.waypoints_file},
                                  std::pair{"trajectory.recording", &options.trajectory.recording},
                                  std::pair{"imu.recording", &options.imu.recording}})
    if (const std::string why = UnsetDataDirReason(*file); !why.empty())
      throw InputError(origin + ": " + key + ": " + why);
  if (!(options.duration_s >= kMinDuration_s))  // 0 kept: a trajectory without an end (ResolveDurationToEnd)
    throw InputError(origin + ": duration_s: must be at least " + FormatDouble(kMinDuration_s) + " s, got " +
                     FormatDouble(options.duration_s) + " s" +
                     (options.duration_s == 0.0 ? " (0, to the end of the trajectory, needs trajectory.type "
                                                  "waypoints or recording)"
                                                : ""));
  const std::string camera = options.camera.Validate();
  if (!camera.empty()) throw InputError(origin + ": camera." + camera);
  if (options.glitch.enabled && options.glitch.axes.empty())
    throw InputError(origin + ": glitch.axes: must name at least one axis when glitch.enabled is true");
  if (options.imu.rate_hz < options.camera.rate_hz)
    throw InputError(origin + ": imu.rate_hz: must be at least camera.rate_hz");
  if (options.imu.noise.initial_gyro_bias.size() != 3)
    throw InputError(origin + ": imu.noise.initial_gyro_bias: expected 3 numbers (x, y, z)");
  if (options.imu.noise.initial_accel_bias.size() != 3)
    throw InputError(origin + ": imu.noise.initial_accel_bias: expected 3 numbers (x, y, z)");
  if (options.duration_s * options.imu.rate_hz > kMaxImuSamples)
    throw InputError(origin + ": duration_s: duration_s x imu.rate_hz must be at most " +
                     std::to_string(static_cast<long long>(kMaxImuSamples)) + " IMU samples");
  for (std::size_t i = 0; i < options.glitch.axes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (options.glitch.axes[i] == options.glitch.axes[j])
        throw InputError(origin + ": glitch.axes: axis " + ImuAxisName(options.glitch.axes[i]) +
                         " listed twice");
  const std::string faults = ValidateFaultOptions(options.faults, options.gravity_mps2);
  if (!faults.empty()) throw InputError(origin + ": faults." + faults);
  if (options.landmarks.layout != LandmarkLayout::kHouse && options.landmarks.random_count <= 0)
    throw InputError(origin +
                     ": landmarks.random_count: must be > 0 for the layouts random and house+random");
  if (options.imu.source == ImuSource::kRecording && options.imu.recording.empty())
    throw InputError(origin + ": imu.recording: required for imu.source recording");
  if (options.imu.source == ImuSource::kRecording && options.images.enabled)
    throw InputError(origin +
                     ": images.enabled: rendered images need a simulated trajectory (imu.source simulated)");
  if (options.trajectory.type == TrajectoryType::kWaypoints && options.trajectory.waypoints_file.empty())
    throw InputError(origin + ": trajectory.waypoints_file: required for trajectory.type waypoints");
  if (options.trajectory.type == TrajectoryType::kRecording && options.trajectory.recording.empty())
    throw InputError(origin + ": trajectory.recording: required for trajectory.type recording");
}

}  // namespace vigil::sim
