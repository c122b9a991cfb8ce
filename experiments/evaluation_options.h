// Options of the trajectory evaluation (rpg_trajectory_evaluation definitions).
#pragma once

#include <vector>

#include "core/config.h"

namespace vigil::experiments {

enum class Alignment { kPosYaw, kSe3, kSim3, kNone };

inline const config::EnumNames<Alignment>& AlignmentNames() {
  static const config::EnumNames<Alignment> names = {{"posyaw", Alignment::kPosYaw},
                                                     {"se3", Alignment::kSe3},
                                                     {"sim3", Alignment::kSim3},
                                                     {"none", Alignment::kNone}};
  return names;
}

struct EvaluationOptions {
  Alignment align = Alignment::kPosYaw;
  std::vector<double> distances_m = {7.0, 14.0, 21.0, 28.0, 35.0};

  template <class V>
  void Visit(V& v) {
    v.Enum("align", align, AlignmentNames(),
           "trajectory alignment before ATE: posyaw (4 DoF), se3, sim3, none");
    v.Field("distances_m", distances_m, "sub-trajectory lengths of the relative error [m]",
            config::Bounds::Positive());
  }
};

}  // namespace vigil::experiments
