#include "evaluation/coverage.h"

#include <gtest/gtest.h>

namespace vigil::evaluation {
namespace {

constexpr int64_t kMillisecondNs = 1'000'000;

// A 40 Hz ground truth over 3 s, and an estimate at 10 Hz (every fourth ground-truth time) from 0.5 to 1.5 s
// and from 2.0 to 2.5 s: a half-second gap, as a reset leaves.
struct Streams {
  std::vector<int64_t> gt_ns, est_ns;
};

Streams TenHzWithAGap() {
  Streams s;
  for (int k = 0; k < 120; ++k) s.gt_ns.push_back(k * 25 * kMillisecondNs);
  for (int t_ms = 500; t_ms <= 1500; t_ms += 100) s.est_ns.push_back(t_ms * kMillisecondNs);
  for (int t_ms = 2000; t_ms <= 2500; t_ms += 100) s.est_ns.push_back(t_ms * kMillisecondNs);
  return s;
}

TEST(Coverage, PosesBetweenCloseEstimatesAreCovered) {
  const Streams s = TenHzWithAGap();
  const auto matches = AssociateTimestamps(s.est_ns, s.gt_ns);
  ASSERT_EQ(matches.size(), 17u);
  // 0.5-1.5 s holds 41 ground-truth poses, 2.0-2.5 s 21; the gap between 1.5 and 2.0 s is not covered.
  EXPECT_EQ(CoveredPoses(s.est_ns, s.gt_ns, matches, 250 * kMillisecondNs), 62u);
  EXPECT_EQ(CoveredPoses(s.est_ns, s.gt_ns, matches, 500 * kMillisecondNs), 120u - 20u - 19u);
}

TEST(Coverage, ZeroGapCountsTheAssociatedPosesOnly) {
  const Streams s = TenHzWithAGap();
  const auto matches = AssociateTimestamps(s.est_ns, s.gt_ns);
  EXPECT_EQ(CoveredPoses(s.est_ns, s.gt_ns, matches, 0), matches.size());
  EXPECT_EQ(CoveredPoses(s.est_ns, s.gt_ns, matches, 99 * kMillisecondNs), matches.size());
}

TEST(Coverage, AnEstimateOffTheGroundTruthTimesStillCovers) {
  // Estimate poses 12.5 ms off the ground truth's times: each associates with one pose, and the poses between
  // consecutive estimates are covered by the gap rule.
  std::vector<int64_t> gt_ns, est_ns;
  for (int k = 0; k < 40; ++k) gt_ns.push_back(k * 25 * kMillisecondNs);
  for (int k = 0; k < 10; ++k) est_ns.push_back(k * 100 * kMillisecondNs + 12'500'000);
  const auto matches = AssociateTimestamps(est_ns, gt_ns);
  EXPECT_EQ(matches.size(), 10u);
  // Ground truth from 12.5 ms to 912.5 ms: poses 1-36, plus pose 0, associated with the first estimate.
  EXPECT_EQ(CoveredPoses(est_ns, gt_ns, matches, 100 * kMillisecondNs), 37u);
  EXPECT_EQ(CoveredPoses({}, gt_ns, {}, 100 * kMillisecondNs), 0u);
}

}  // namespace
}  // namespace vigil::evaluation
