#include "sim/camera_timing.h"

#include <algorithm>
#include <cmath>

#include "core/random.h"

namespace vigil::sim {

std::vector<int64_t> ApplyCameraTiming(const CameraTimingOptions& options, double rate_hz, uint64_t seed,
                                       std::vector<int64_t> times_ns) {
  if (times_ns.size() < 3 || (options.drop_rate <= 0.0 && options.jitter_std_s <= 0.0)) return times_ns;
  const double max_jitter_ns = 0.45e9 / rate_hz;
  Rng drop(seed, "camera_drop"), jitter(seed, "camera_jitter");
  std::vector<int64_t> out{times_ns.front()};
  for (std::size_t k = 1; k + 1 < times_ns.size(); ++k) {
    const bool dropped = options.drop_rate > 0.0 && drop.Uniform() < options.drop_rate;
    double dt_ns = 0.0;
    if (options.jitter_std_s > 0.0)
      dt_ns = std::clamp(options.jitter_std_s * 1e9 * jitter.Normal(), -max_jitter_ns, max_jitter_ns);
    if (!dropped) out.push_back(times_ns[k] + std::llround(dt_ns));
  }
  out.push_back(times_ns.back());
  return out;
}

}  // namespace vigil::sim
