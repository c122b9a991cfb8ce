// Reading a sweep run's metrics.json back (`vigil tables`, `vigil regress`, the end of `vigil sweep`): the
// file is input like any other, so it is checked before a table counts it (formats.md gives its keys; keys
// may be added, and unknown ones are ignored). Refused, with "FILE:LINE: key: reason":
//   - anything but a JSON object, a "status" other than "ok", "diverged", "inconclusive" or "failed";
//   - a "seed" that is not the run's (the metrics of another run copied in; a run that failed before it
//     started has none);
//   - where present: ate/relative statistics that are not numbers (null allowed) in [0, kMaxMetricValue],
//     a "relative" that is not a list of {distance_m > 0, trans_m, yaw_deg}, detection counts that are not
//     integers >= 0, precision/recall/f1 outside [0, 1], wall times that are not numbers >= 0.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "core/output.h"

namespace vigil::experiments {

// The largest error or duration a metrics.json may give (1e9 m, deg or s: beyond it a value is corrupt).
inline constexpr double kMaxMetricValue = 1e9;

// Reads and checks `path`, the metrics of the run whose seed is `seed`; returns the parsed object.
nlohmann::json ReadRunMetrics(const std::string& path, uint64_t seed);
// The same on a file already in memory.
nlohmann::json ReadRunMetricsText(const TextFile& file, uint64_t seed);

}  // namespace vigil::experiments
