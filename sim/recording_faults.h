// The simulator's IMU fault models applied to a recorded IMU stream (`vigil inject`).
//
// The recording takes the place of step 1 of imu_faults.h (synthesis): its own samples and timestamps are
// the sensor, and steps 2-6 follow in the simulator's order with the simulator's keys (glitch.*, faults.*)
// and random streams, so a recording and a simulation given the same keys and seed fault alike:
//   clean := the recording's glitch-free stream (its imu_clean when it has one, else its imu);
//   measured := its imu;
//   2. scale / misalignment on both; 3. glitches on measured; 4-6. saturation, quantization, timing faults.
// Glitch records the recording already had are kept (merged in time order with the new ones).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/types.h"
#include "sim/fault_options.h"
#include "sim/sim_options.h"

namespace vigil::sim {

struct RecordingFaultOptions {
  uint64_t seed = 1;
  double gravity_mps2 = 9.81;
  GlitchOptions glitch;
  FaultOptions faults;

  template <class V>
  void Visit(V& v) {
    v.Field("seed", seed, "seed of the fault draws (the simulator's streams: glitch, glitch_offset, timing)");
    v.Field("gravity_mps2", gravity_mps2, "magnitude g of gravity [m/s^2] (saturation ranges given in g)",
            config::Bounds{0.0, 100.0, true, false});
    v.Section("glitch", glitch, "offset glitches, as in the simulator");
    v.Section("faults", faults, "low-cost IMU faults besides the glitches, as in the simulator");
  }
};

struct FaultedRecording {
  ImuStream imu;                       // with the faults
  ImuStream imu_clean;                 // the recording's own stream (steps 2, 5, 6 applied alike)
  std::vector<GlitchRecord> glitches;  // the recording's records and the new ones, in time order
};

// `recorded`: the recording's IMU (at least 2 samples); `recorded_clean`: empty or sample-aligned with it;
// `recorded_glitches`: its glitches.csv (records on a recording without `recorded_clean` are refused by the
// caller: their clean values are unknown). std::invalid_argument on invalid options (the caller checks
// ValidateRecordingFaultOptions first).
FaultedRecording InjectIntoRecording(const RecordingFaultOptions& options, const ImuStream& recorded,
                                     const ImuStream& recorded_clean,
                                     const std::vector<GlitchRecord>& recorded_glitches);

// Cross-field checks (faults.*); empty when valid, else "key: reason". faults.camera.* other than 0 is
// refused: a recording's camera frames are not touched.
std::string ValidateRecordingFaultOptions(const RecordingFaultOptions& options);

}  // namespace vigil::sim
