// Quantization of every IMU sample to the sensor's resolution (fault_options.h: QuantizationOptions): each
// axis is rounded to the nearest multiple of its LSB. Deterministic; it touches every sample, so it is not
// recorded per sample (the configuration states it).
#pragma once

#include "core/types.h"
#include "sim/fault_options.h"

namespace vigil::sim {

void ApplyQuantization(const QuantizationOptions& options, ImuStream* imu);

}  // namespace vigil::sim
