#include "sim/recording_faults.h"

#include <algorithm>
#include <stdexcept>

#include "sim/glitch_injector.h"
#include "sim/imu_faults.h"
#include "sim/scale_misalignment.h"

namespace vigil::sim {

std::string ValidateRecordingFaultOptions(const RecordingFaultOptions& options) {
  // A recording's camera frames are its own: camera timing faults are the simulator's alone.
  if (options.faults.camera.drop_rate != 0.0 || options.faults.camera.jitter_std_s != 0.0)
    return std::string("faults.camera.") +
           (options.faults.camera.drop_rate != 0.0 ? "drop_rate" : "jitter_std_s") +
           ": inject applies IMU faults only; a recording's camera frames are kept as recorded (camera "
           "timing "
           "faults are simulated by vigil simulate and vigil run)";
  const std::string why = ValidateFaultOptions(options.faults, options.gravity_mps2);
  return why.empty() ? why : "faults." + why;
}

FaultedRecording InjectIntoRecording(const RecordingFaultOptions& options, const ImuStream& recorded,
                                     const ImuStream& recorded_clean,
                                     const std::vector<GlitchRecord>& recorded_glitches) {
  if (recorded.size() < 2) throw std::invalid_argument("InjectIntoRecording: fewer than two IMU samples");
  if (!recorded_clean.empty() && recorded_clean.size() != recorded.size())
    throw std::invalid_argument("InjectIntoRecording: the clean stream is not sample-aligned with the IMU");
  const std::string why = ValidateRecordingFaultOptions(options);
  if (!why.empty()) throw std::invalid_argument("InjectIntoRecording: " + why);

  FaultedRecording out;
  out.imu_clean = recorded_clean.empty() ? recorded : recorded_clean;
  out.imu = recorded;
  // 2. Constant scale and misalignment: the sensor's, on every sample of both streams.
  ApplyScaleMisalignment(options.faults.scale, &out.imu_clean);
  ApplyScaleMisalignment(options.faults.scale, &out.imu);
  // 3. Offset glitches on the measured stream, merged with the recording's own records.
  std::vector<GlitchRecord> added = InjectGlitches(options.glitch, options.seed, &out.imu);
  out.glitches = recorded_glitches;
  out.glitches.insert(out.glitches.end(), added.begin(), added.end());
  std::stable_sort(out.glitches.begin(), out.glitches.end(),
                   [](const GlitchRecord& a, const GlitchRecord& b) { return a.t_ns < b.t_ns; });
  // 4-6. Saturation, quantization, timing faults, at the recording's mean rate.
  SimOptions sim;
  sim.gravity_mps2 = options.gravity_mps2;
  sim.glitch = options.glitch;
  sim.faults = options.faults;
  sim.imu.rate_hz =
      static_cast<double>(recorded.size() - 1) / NsToS(recorded.back().t_ns - recorded.front().t_ns);
  ApplyMeasurementFaults(sim, options.seed, &out.imu, &out.imu_clean, &out.glitches);
  return out;
}

}  // namespace vigil::sim
