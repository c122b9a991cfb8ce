#include "sim/glitch_injector.h"

#include "core/random.h"

namespace vigil::sim {

std::vector<GlitchRecord> InjectGlitches(const GlitchOptions& options, uint64_t seed, ImuStream* imu) {
  std::vector<GlitchRecord> records;
  if (!options.enabled) return records;
  Rng onset_rng(seed, "glitch");
  Rng offset_rng(seed, "glitch_offset");
  int remaining = 0;  // samples left in the current burst
  for (ImuSample& sample : *imu) {
    if (onset_rng.Bernoulli(options.rate)) remaining = options.burst_length;
    if (remaining == 0) continue;
    --remaining;
    for (const ImuAxis axis : options.axes) {
      const double offset = offset_rng.Normal(options.mean, options.std);
      sample.axis(static_cast<int>(axis)) += offset;
      records.push_back({sample.t_ns, axis, offset});
    }
  }
  return records;
}

}  // namespace vigil::sim
