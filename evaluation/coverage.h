// Which ground-truth poses an estimated trajectory covers (TrajectoryEvaluation::coverage).
//
// A ground-truth pose is covered when an estimate pose was associated with it, or when it lies between two
// consecutive estimate poses at most `max_gap_ns` apart. An estimator that outputs fewer poses than the
// ground truth has, such as one solving 10 of a 30 Hz camera's frames per second, then covers the time it
// tracked rather than a third of it; a gap longer than max_gap_ns (a reset, a stop) stays uncovered.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "evaluation/association.h"

namespace vigil::evaluation {

// `est_ns` and `gt_ns` strictly increasing; `matches` from AssociateTimestamps on them.
std::size_t CoveredPoses(const std::vector<int64_t>& est_ns, const std::vector<int64_t>& gt_ns,
                         const std::vector<MatchedIndices>& matches, int64_t max_gap_ns);

}  // namespace vigil::evaluation
