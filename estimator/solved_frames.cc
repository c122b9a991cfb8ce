#include "estimator/solved_frames.h"

#include <algorithm>

namespace vigil::estimator {

bool RateAllows(int64_t last_ns, int64_t t_ns, double max_rate_hz) {
  return max_rate_hz <= 0.0 || static_cast<double>(t_ns - last_ns) >= 0.9e9 / max_rate_hz;
}

bool AnyFlaggedSample(const ImuStream& imu, const std::vector<uint8_t>& flagged, int64_t after_ns,
                      int64_t until_ns) {
  if (flagged.empty()) return false;
  const auto first = std::upper_bound(imu.begin(), imu.end(), after_ns,
                                      [](int64_t t_ns, const ImuSample& s) { return t_ns < s.t_ns; });
  for (auto it = first; it != imu.end() && it->t_ns <= until_ns; ++it)
    if (flagged[static_cast<std::size_t>(it - imu.begin())]) return true;
  return false;
}

}  // namespace vigil::estimator
