// Reading the trajectory an external estimator wrote: input like any other, so it is size- and value-checked
// and every problem becomes a reason the run failed, never a crash.
//
// Formats (experiments/external/external_estimator_options.h):
//   tum    "t x y z qx qy qz qw[ more columns]" separated by spaces or tabs ('#' comment lines allowed;
//          OpenVINS appends covariance columns)
//   euroc  "t,x,y,z,qw,qx,qy,qz[,more columns]" separated by commas (a '#' header line allowed)
// Times in seconds (decimal, read exactly to the nanosecond) or integer nanoseconds. Positions in metres,
// the body (IMU) pose in the world frame.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/types.h"
#include "experiments/external/external_estimator_options.h"

namespace vigil::experiments {

// Largest trajectory file read, and the slack around the recording's time span that rows may have.
inline constexpr std::uintmax_t kMaxExternalTrajectoryBytes = 512u << 20;
inline constexpr int64_t kExternalTimeSlack_ns = 500000000;

struct ExternalTrajectory {
  Trajectory trajectory;
  std::string failure;  // empty when the file was read; else why the run failed ("trajectory.txt:12: ...")
};

// Reads `path`: rows must be finite, quaternions unit (core/pose_checks.h; normalized unless unit to double
// precision),
// times strictly increasing and inside [t_first_ns - slack, t_last_ns + slack] (a row outside is mostly a
// unit mix-up: nanoseconds read as seconds). An absent or empty file is a failure too.
ExternalTrajectory ReadExternalTrajectory(const std::filesystem::path& path, TrajectoryFormat format,
                                          TimeUnit unit, int64_t t_first_ns, int64_t t_last_ns);

// Empty when `path`, with every symbolic link on it resolved, lies inside `output_dir` (or does not exist:
// the reader says so); else why it is not read ("traj.txt: resolves to /etc/passwd, outside ..."). An
// estimator's trajectory is what it wrote into its {output} folder, never a file elsewhere that a link
// names.
std::string TrajectoryOutsideOutput(const std::filesystem::path& path,
                                    const std::filesystem::path& output_dir);

}  // namespace vigil::experiments
