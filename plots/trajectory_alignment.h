// Aligning an estimated trajectory onto the ground truth for display (figure 3).
//
// The metrics themselves come from the run's metrics.json (experiments' evaluation); this only places the
// estimate in the ground-truth frame with the run's evaluation.align choice so that the curves can be
// compared: posyaw (translation + rotation about gravity, closed form), se3 / sim3 (Umeyama), none.
#pragma once

#include "core/types.h"
#include "experiments/evaluation_options.h"

namespace vigil::plots {

// Poses of `estimate` that have a ground-truth pose within 1 ms, transformed by the best alignment of the
// given kind (least squares over the matched positions). Fewer than 2 matches: the matched poses unchanged.
Trajectory AlignForDisplay(const Trajectory& estimate, const Trajectory& groundtruth,
                           experiments::Alignment alignment);

}  // namespace vigil::plots
