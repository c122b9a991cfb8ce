// Timestamp faults of consumer IMU drivers (fault_options.h: TimingFaultOptions).
//
// Per sample (never the first or the last): with probability drop_rate it is lost (stream "imu_drop"); with
// probability duplicate_rate it carries the timestamp of the sample written before it (stream
// "imu_duplicate"); its timestamp moves by N(0, jitter_std_s), clipped to +-0.45 IMU periods (stream
// "imu_jitter"), so timestamps never go backwards (they may repeat). Each stream is drawn once per sample
// only when its fault is on. Values are untouched: a jittered sample still holds what was sensed at its true
// time, as with a driver that stamps on reception.
//
// Readers accept equal IMU timestamps (core/dataset.h); the estimator keeps the first of equal timestamps and
// integrates over the (uneven) intervals between the remaining ones (estimator/run_estimator.h).
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"
#include "sim/fault_options.h"

namespace vigil::sim {

// Applies the same faults to `imu` and `imu_clean` (equal timestamps, equal length). `records` holds the
// value faults of `imu` (sample order, timestamps of `imu` before this call): the records of a dropped sample
// are removed, the others take the sample's new timestamp; then one record per timing fault is added and the
// whole list is ordered by timestamp (stable).
void ApplyTimingFaults(const TimingFaultOptions& options, double rate_hz, uint64_t seed, ImuStream* imu,
                       ImuStream* imu_clean, std::vector<GlitchRecord>* records);

}  // namespace vigil::sim
