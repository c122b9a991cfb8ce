#include "evaluation/association.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace vigil::evaluation {
namespace {

constexpr int64_t kMs = 1'000'000;

std::vector<std::pair<std::size_t, std::size_t>> Pairs(const std::vector<MatchedIndices>& m) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const auto& x : m) out.emplace_back(x.est, x.gt);
  return out;
}

TEST(Association, ToleranceIsStrictlyBelow20Ms) {
  const std::vector<int64_t> gt = {0, 1000 * kMs, 2000 * kMs, 3000 * kMs};
  const std::vector<int64_t> est = {19 * kMs, 1020 * kMs, 2000 * kMs - 19'999'999, 3021 * kMs};
  using P = std::pair<std::size_t, std::size_t>;
  EXPECT_EQ(Pairs(AssociateTimestamps(est, gt)), (std::vector<P>{{0, 0}, {2, 2}}));
  EXPECT_EQ(Pairs(AssociateTimestamps(est, gt, 25 * kMs)), (std::vector<P>{{0, 0}, {1, 1}, {2, 2}, {3, 3}}));
}

TEST(Association, OneToOneClosestFirst) {
  // Two estimates near the same ground-truth pose: the closer one takes it, the other falls back on its own
  // second-best candidate when that is within tolerance.
  const std::vector<int64_t> gt = {100 * kMs, 115 * kMs};
  const std::vector<int64_t> est = {101 * kMs + 500'000, 103 * kMs};
  const auto m = AssociateTimestamps(est, gt);
  using P = std::pair<std::size_t, std::size_t>;
  EXPECT_EQ(Pairs(m), (std::vector<P>{{0, 0}, {1, 1}}));  // 101.5 -> 100 (1.5 ms), 103 -> 115 (12 ms)
}

TEST(Association, DenseGroundTruthPicksNearest) {
  std::vector<int64_t> gt;  // 200 Hz
  for (int k = 0; k < 400; ++k) gt.push_back(k * 5 * kMs);
  std::vector<int64_t> est;  // 30 Hz, offset by 1 ms
  for (int k = 0; k < 60; ++k) est.push_back(k * 33 * kMs + 1 * kMs);
  const auto m = AssociateTimestamps(est, gt);
  ASSERT_EQ(m.size(), est.size());
  for (const auto& x : m) {
    const int64_t d = std::abs(est[x.est] - gt[x.gt]);
    EXPECT_LE(d, 2'500'000) << x.est;  // the nearest 200 Hz sample is at most 2.5 ms away
  }
}

TEST(Association, RejectsUnorderedInput) {
  EXPECT_THROW(AssociateTimestamps({2, 1}, {0}), std::invalid_argument);
  EXPECT_TRUE(AssociateTimestamps({}, {1, 2}).empty());
}

}  // namespace
}  // namespace vigil::evaluation
