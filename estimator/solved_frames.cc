#include "estimator/solved_frames.h"

namespace vigil::estimator {

bool RateAllows(int64_t last_ns, int64_t t_ns, double max_rate_hz) {
  return max_rate_hz <= 0.0 || static_cast<double>(t_ns - last_ns) >= 0.9e9 / max_rate_hz;
}

bool FramePace::Take(int64_t t_ns) {
  if (last_ns_ && !RateAllows(*last_ns_, t_ns, max_rate_hz_)) return false;
  last_ns_ = t_ns;
  return true;
}

}  // namespace vigil::estimator
