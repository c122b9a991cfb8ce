// Noise figures of IMU classes (imu.preset), from their datasheets or published calibrations; the sources are
// in docs/imu-models.md.
//
// A preset provides the defaults of imu.noise.*: white-noise densities, bias random walks and the spread of
// the bias at switch-on. Keys a config writes still win (the run config is loaded a second time over the
// preset's values). ImuPreset::kNone leaves vigil's own defaults.
#pragma once

#include "sim/sim_options.h"

namespace vigil::sim {

// Writes the preset's figures into `imu->noise` (enabled = true); kNone changes nothing.
void ApplyImuPreset(ImuPreset preset, ImuOptions* imu);

}  // namespace vigil::sim
