// Saturation (clipping) of each IMU axis at the sensor's full-scale range (fault_options.h:
// SaturationOptions). Deterministic. Each clipped (sample, axis) is recorded with kind saturation and the
// change it made (clipped - unclipped value).
#pragma once

#include <vector>

#include "core/types.h"
#include "sim/fault_options.h"

namespace vigil::sim {

// Clips `imu` in place to +-range (0: that sensor is unbounded); appends one record per clipped axis to
// `records` when not null, in sample order then axis order.
void ApplySaturation(double accel_range_mps2, double gyro_range_radps, ImuStream* imu,
                     std::vector<GlitchRecord>* records);

}  // namespace vigil::sim
