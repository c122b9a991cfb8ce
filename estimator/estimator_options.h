// Options of the sliding-window visual-inertial estimator.
#pragma once

#include "core/config.h"

namespace vigil::estimator {

enum class InitMode { kGroundTruth, kVins };

struct EstimatorOptions {
  InitMode init = InitMode::kGroundTruth;

  template <class V>
  void Visit(V& v) {
    v.Enum("init", init,
           config::EnumNames<InitMode>{{"groundtruth", InitMode::kGroundTruth}, {"vins", InitMode::kVins}},
           "initialization: groundtruth (first window from ground truth) or vins (visual-inertial, no ground truth)");
  }
};

}  // namespace vigil::estimator
