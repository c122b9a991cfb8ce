// Irregular camera frames (fault_options.h: CameraTimingOptions): a camera whose frames are not on the
// nominal rate's grid, and frames lost on the way.
//
// Per frame (never the first or the last): with probability drop_rate it is lost (stream "camera_drop"); its
// time moves by N(0, jitter_std_s), clipped to +-0.45 nominal periods (stream "camera_jitter"), so frames
// stay in order and distinct. The feature tracks are then taken at the moved times: the frame shows the
// scene at its own timestamp, as with a real camera whose clock is irregular. Each stream is drawn only when
// its fault is on; with both off the times are returned unchanged.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/fault_options.h"

namespace vigil::sim {

std::vector<int64_t> ApplyCameraTiming(const CameraTimingOptions& options, double rate_hz, uint64_t seed,
                                       std::vector<int64_t> times_ns);

}  // namespace vigil::sim
