#include "evaluation/coverage.h"

#include <algorithm>

namespace vigil::evaluation {

std::size_t CoveredPoses(const std::vector<int64_t>& est_ns, const std::vector<int64_t>& gt_ns,
                         const std::vector<MatchedIndices>& matches, int64_t max_gap_ns) {
  std::vector<bool> covered(gt_ns.size(), false);
  for (const MatchedIndices& m : matches) covered[m.gt] = true;
  for (std::size_t j = 0; j < gt_ns.size(); ++j) {
    if (covered[j]) continue;
    // The first estimate pose at or after the ground-truth pose, and the one before it.
    const auto after = std::lower_bound(est_ns.begin(), est_ns.end(), gt_ns[j]);
    if (after == est_ns.end()) continue;
    if (*after == gt_ns[j]) {
      covered[j] = true;
      continue;
    }
    if (after == est_ns.begin()) continue;
    covered[j] = *after - *(after - 1) <= max_gap_ns;
  }
  return static_cast<std::size_t>(std::count(covered.begin(), covered.end(), true));
}

}  // namespace vigil::evaluation
