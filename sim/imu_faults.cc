#include "sim/imu_faults.h"

#include "sim/quantization.h"
#include "sim/saturation.h"
#include "sim/timing_faults.h"

namespace vigil::sim {

void ApplyMeasurementFaults(const SimOptions& options, uint64_t seed, ImuStream* imu, ImuStream* imu_clean,
                            std::vector<GlitchRecord>* records) {
  const FaultOptions& faults = options.faults;
  std::vector<GlitchRecord> unrecorded;
  std::vector<GlitchRecord>* out = records ? records : &unrecorded;
  // Clipping records are merged into the glitch records in sample order.
  std::vector<GlitchRecord> clipped;
  ApplySaturation(AccelRangeMps2(faults.saturation, options.gravity_mps2), GyroRangeRadps(faults.saturation),
                  imu, &clipped);
  if (!clipped.empty()) {
    std::vector<GlitchRecord> merged;
    merged.reserve(out->size() + clipped.size());
    std::size_t c = 0;
    for (const GlitchRecord& g : *out) {
      while (c < clipped.size() && clipped[c].t_ns < g.t_ns) merged.push_back(clipped[c++]);
      merged.push_back(g);
    }
    while (c < clipped.size()) merged.push_back(clipped[c++]);
    *out = std::move(merged);
  }
  ApplyQuantization(faults.quantization, imu);
  ApplyQuantization(faults.quantization, imu_clean);
  ApplyTimingFaults(faults.timing, options.imu.rate_hz, seed, imu, imu_clean, out);
}

}  // namespace vigil::sim
