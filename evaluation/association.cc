#include "evaluation/association.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <tuple>

namespace vigil::evaluation {
namespace {

void CheckIncreasing(const std::vector<int64_t>& t_ns, const char* what) {
  for (std::size_t i = 1; i < t_ns.size(); ++i)
    if (t_ns[i] <= t_ns[i - 1])
      throw std::invalid_argument(std::string("AssociateTimestamps: ") + what +
                                  " timestamps do not increase at " + std::to_string(i));
}

struct Candidate {
  int64_t difference_ns;
  std::size_t est, gt;
  bool operator<(const Candidate& o) const {
    return std::tie(difference_ns, est, gt) < std::tie(o.difference_ns, o.est, o.gt);
  }
};

}  // namespace

std::vector<MatchedIndices> AssociateTimestamps(const std::vector<int64_t>& est_ns,
                                                const std::vector<int64_t>& gt_ns,
                                                int64_t max_difference_ns) {
  CheckIncreasing(est_ns, "estimate");
  CheckIncreasing(gt_ns, "ground-truth");
  // Both lists are sorted: the candidates of estimate i are a window of ground-truth indices that only moves
  // forward with i.
  std::vector<Candidate> candidates;
  std::size_t window_begin = 0;
  for (std::size_t i = 0; i < est_ns.size(); ++i) {
    while (window_begin < gt_ns.size() && gt_ns[window_begin] <= est_ns[i] - max_difference_ns)
      ++window_begin;
    for (std::size_t j = window_begin; j < gt_ns.size() && gt_ns[j] < est_ns[i] + max_difference_ns; ++j)
      candidates.push_back({std::abs(gt_ns[j] - est_ns[i]), i, j});
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> est_used(est_ns.size(), false), gt_used(gt_ns.size(), false);
  std::vector<MatchedIndices> matches;
  for (const Candidate& c : candidates) {
    if (est_used[c.est] || gt_used[c.gt]) continue;
    est_used[c.est] = gt_used[c.gt] = true;
    matches.push_back({c.est, c.gt});
  }
  std::sort(matches.begin(), matches.end(),
            [](const MatchedIndices& a, const MatchedIndices& b) { return a.est < b.est; });
  return matches;
}

}  // namespace vigil::evaluation
