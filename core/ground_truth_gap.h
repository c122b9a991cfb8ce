// The longest gap a recorded ground truth may have between two rows, shared by every reader of one (a
// dataset's groundtruth.csv, EuRoC's state_groundtruth_estimate0, trajectory.recording): across a longer gap
// the motion is unknown, and a spline or an interpolation through it would invent one.
#pragma once

#include <cstdint>
#include <string>

#include "core/format.h"

namespace vigil {

inline constexpr int64_t kMaxGroundTruthGap_ns = 1000000000;  // 1 s

// Why a gap of `gap_s` between two rows (beyond kMaxGroundTruthGap_ns) is refused.
inline std::string GroundTruthGapReason(double gap_s) {
  return "no pose for " + FormatDouble(gap_s) + " s since the previous row (more than the limit of " +
         FormatDouble(static_cast<double>(kMaxGroundTruthGap_ns) * 1e-9) +
         " s): the motion across the gap is unknown; split the recording there";
}

}  // namespace vigil
