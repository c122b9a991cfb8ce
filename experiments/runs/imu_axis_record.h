// imu_axis.csv of a run directory: one IMU axis of every sample the run read, as measured, without the
// injected glitches and after mitigation, with the detector's flag; what figures 2 and 5 draw (plots/ reads
// it instead of re-simulating the run or re-running its detector).
//
// Layout (one '#' header line, comma separated, doubles in shortest round-trip form):
//   #timestamp [ns],raw AX,clean AX,mitigated AX,flagged
// AX is the axis name of core/types.h (wx ... az; the run's first glitch.axes entry, az when none), values in
// rad/s (gyroscope) or m/s^2 (accelerometer). The clean column is left out (4 columns) when the recording has
// no glitch-free stream (a dataset without imu_clean.csv). Without a detector, mitigated = raw and flagged =
// 0.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/types.h"

namespace vigil::experiments {

inline constexpr const char* kImuAxisFile = "imu_axis.csv";

struct ImuAxisRecord {
  ImuAxis axis = ImuAxis::kAz;
  std::vector<int64_t> t_ns;
  std::vector<double> raw, clean, mitigated;  // clean is empty when the recording had no glitch-free stream
  std::vector<uint8_t> flagged;
};

// The record of `axis`: `clean` may be null (no glitch-free stream) or must match `raw` like `mitigated` and
// `flagged` (same length; std::invalid_argument otherwise).
ImuAxisRecord MakeImuAxisRecord(ImuAxis axis, const ImuStream& raw, const ImuStream* clean,
                                const ImuStream& mitigated, const std::vector<uint8_t>& flagged);

std::string ImuAxisCsv(const ImuAxisRecord& record);
// InputError "file:line: reason" on a bad header, a non-finite value, a flag other than 0/1 or timestamps
// that do not increase strictly.
ImuAxisRecord ReadImuAxisCsv(const std::string& path);

}  // namespace vigil::experiments
