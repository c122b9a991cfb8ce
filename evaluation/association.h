// Timestamp association of an estimated trajectory with its ground truth (rpg_trajectory_evaluation's rule).
//
// Every pair (estimate i, ground truth j) whose timestamps differ by less than `max_difference_ns` is a
// candidate; candidates are taken in order of increasing difference (ties: lower estimate index, then lower
// ground-truth index) and a pair is kept when neither of its poses is matched yet. The result is one-to-one
// and sorted by estimate index (hence also by ground-truth index, for increasing timestamps).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vigil::evaluation {

// rpg's default tolerance: 0.02 s.
inline constexpr int64_t kDefaultMaxAssociationDifferenceNs = 20'000'000;

struct MatchedIndices {
  std::size_t est = 0;
  std::size_t gt = 0;
};

// `est_ns` and `gt_ns` must be strictly increasing (std::invalid_argument otherwise).
std::vector<MatchedIndices> AssociateTimestamps(
    const std::vector<int64_t>& est_ns, const std::vector<int64_t>& gt_ns,
    int64_t max_difference_ns = kDefaultMaxAssociationDifferenceNs);

}  // namespace vigil::evaluation
