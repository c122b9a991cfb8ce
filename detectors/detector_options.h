// Options of the glitch detectors and their mitigation.
#pragma once

#include "core/config.h"

namespace vigil::detectors {

enum class DetectorType { kNone, kThreshold, kDtw, kHampel };

inline const config::EnumNames<DetectorType>& DetectorTypeNames() {
  static const config::EnumNames<DetectorType> names = {{"none", DetectorType::kNone},
                                                        {"threshold", DetectorType::kThreshold},
                                                        {"dtw", DetectorType::kDtw},
                                                        {"hampel", DetectorType::kHampel}};
  return names;
}

struct DetectorOptions {
  DetectorType type = DetectorType::kNone;

  template <class V>
  void Visit(V& v) {
    v.Enum("type", type, DetectorTypeNames(), "glitch detector + mitigation applied to the IMU stream");
  }
};

}  // namespace vigil::detectors
