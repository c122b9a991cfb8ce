// `vigil inject` without the process: the simulator's IMU faults (glitch.*, faults.*) applied to a
// recording's IMU, written as a copy of the recording with labels (sim/recording_faults.h).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/recording_copy.h"
#include "core/types.h"

namespace vigil::experiments {

struct InjectRequest {
  std::string dataset;                 // a vigil dataset directory or a EuRoC folder (holding mav0/)
  std::string output;                  // the directory to write
  std::vector<std::string> overrides;  // glitch.*, faults.*, seed, gravity_mps2 (key.path=value), in order
  std::string seed;                    // empty: the options' seed; else applied last as seed=SEED
  bool force = false;                  // replace an output directory vigil wrote
};

struct InjectResult {
  std::size_t imu_samples_in = 0, imu_samples_out = 0;
  std::vector<GlitchRecord> glitches;  // the fault records written to glitches.csv
  RecordingCopyStats copied;
};

// Checks the options and reads the recording first (InputError, nothing written: bad overrides, not a
// dataset directory, mav0/ itself, fewer than two IMU samples, glitches without imu_clean.csv). Then writes a
// copy of the recording into `output` (staged, refused over the recording, and when not empty unless
// `force`): its IMU file(s) with the faults, imu_clean.csv (the recording's own stream), glitches.csv and
// injection.yaml (source, layout, options); images are linked, not copied.
InjectResult InjectRecording(const InjectRequest& request);

// The line `vigil inject` reports (without "vigil inject: " and the newline).
std::string InjectSummary(const InjectRequest& request, const InjectResult& result);

}  // namespace vigil::experiments
