// Injection of IMU glitches: short bursts of large extra noise, the fault model of the paper.
//
// For every IMU sample, with probability `rate` a glitch starts there (stream "glitch"); it affects that
// sample and the next burst_length - 1 (a glitch starting inside a burst restarts the count, so bursts
// merge). On each affected sample, every axis of `axes` gets an independent offset drawn from N(mean, std)
// (stream "glitch_offset", so where glitches fall does not depend on their size or on the axes). Each
// (sample, axis) offset is recorded once, in sample order then axis order of `axes`.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"
#include "sim/sim_options.h"

namespace vigil::sim {

// Adds glitches to `imu` in place and returns them. Does nothing (and returns nothing) when !options.enabled.
std::vector<GlitchRecord> InjectGlitches(const GlitchOptions& options, uint64_t seed, ImuStream* imu);

}  // namespace vigil::sim
