// Aligning an estimated trajectory onto the ground truth for display (figure 3).
//
// The metrics themselves come from the run's metrics.json; this places the estimate in the ground-truth frame
// the way the evaluation does (evaluation/association.h and evaluation/alignment.h, with the run's
// evaluation.align) so that the curves can be compared.
#pragma once

#include "core/types.h"
#include "evaluation/evaluation_options.h"

namespace vigil::plots {

// The poses of `estimate` associated with a ground-truth pose (rpg rule, within 0.02 s), transformed by the
// alignment of the given kind over the matched positions. Timestamps must increase strictly.
Trajectory AlignForDisplay(const Trajectory& estimate, const Trajectory& groundtruth,
                           evaluation::Alignment alignment);

}  // namespace vigil::plots
