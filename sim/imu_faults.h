// The chain of IMU faults of a simulated recording, in the order a low-cost sensor produces them:
//
//   1. synthesis: ideal IMU + bias + white noise (imu_synthesizer.h); the ground truth contains every real
//      motion, the rescue course's steps and bumps included: those peaks are normal measurements, not faults
//   2. constant scale-factor and misalignment errors (scale_misalignment.h)      -> imu and imu_clean
//   3. the paper's offset glitches, bursts included (glitch_injector.h)          -> imu only
//   4. saturation at the full-scale range (saturation.h): clips real peaks and glitches alike, so a glitch
//      on top of a large reading may be cut short (both records are kept)        -> imu only
//   5. quantization to the LSB (quantization.h)                                 -> imu and imu_clean
//   6. timing faults: drops, duplicated and jittered timestamps (timing_faults.h) -> imu and imu_clean
//
// imu_clean is therefore what a perfect detector + mitigator could recover (the sensor without its per-sample
// faults: offsets and clipping) and stays sample-aligned with imu. Steps 3, 4 and 6 are recorded sample by
// sample with their kind (core/types.h FaultKind); 2 and 5 touch every sample identically and are stated by
// the configuration. Every step is off by default and then changes nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"
#include "sim/sim_options.h"

namespace vigil::sim {

// Steps 4-6 on `imu` (after steps 2-3) and `imu_clean` (after step 2); `records` holds the glitches of step 3
// and receives the records of steps 4 and 6 (may be null: nothing recorded).
void ApplyMeasurementFaults(const SimOptions& options, uint64_t seed, ImuStream* imu, ImuStream* imu_clean,
                            std::vector<GlitchRecord>* records);

}  // namespace vigil::sim
