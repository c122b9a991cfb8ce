#include "sim/saturation.h"

#include <algorithm>

namespace vigil::sim {

void ApplySaturation(double accel_range_mps2, double gyro_range_radps, ImuStream* imu,
                     std::vector<GlitchRecord>* records) {
  if (accel_range_mps2 <= 0.0 && gyro_range_radps <= 0.0) return;
  for (ImuSample& s : *imu) {
    for (int i = 0; i < kNumImuAxes; ++i) {
      const double range = i < 3 ? gyro_range_radps : accel_range_mps2;
      if (range <= 0.0) continue;
      const double before = s.axis(i);
      const double clipped = std::clamp(before, -range, range);
      if (clipped == before) continue;
      s.axis(i) = clipped;
      if (records)
        records->push_back({s.t_ns, static_cast<ImuAxis>(i), clipped - before, FaultKind::kSaturation});
    }
  }
}

}  // namespace vigil::sim
