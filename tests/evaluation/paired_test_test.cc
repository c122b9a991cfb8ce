// The paired bootstrap test over seeds (evaluation/paired_test.h) on synthetic per-seed errors.
#include "evaluation/paired_test.h"

#include <gtest/gtest.h>

#include "core/random.h"

namespace vigil::evaluation {
namespace {

// Ten seeds of base + offset + seed-to-seed noise of the given std (shared noise when `shared` is true: a
// paired design sees through it).
SeedValues Series(double mean, double noise_std, uint64_t stream) {
  Rng rng(stream, "series");
  SeedValues v;
  for (uint64_t seed = 1; seed <= 10; ++seed) v[seed] = mean + noise_std * rng.Normal();
  return v;
}

SeedValues Shifted(const SeedValues& base, double shift, double noise_std, uint64_t stream) {
  Rng rng(stream, "shift");
  SeedValues v;
  for (const auto& [seed, x] : base) v[seed] = x + shift + noise_std * rng.Normal();
  return v;
}

TEST(PairedTest, AClearWinHoldsAClearLossDoesNotAndATieIsInconclusive) {
  const SeedValues base = Series(0.3, 0.1, 1);
  const SeedValues better = Shifted(base, -0.05, 0.01, 2), worse = Shifted(base, 0.05, 0.01, 3),
                   same = Shifted(base, 0.0, 0.01, 4);
  const PairedTest win = ComparePaired(better, base, "win");
  EXPECT_EQ(win.pairs, 10u);
  EXPECT_LT(win.ci_high, 0.0);
  EXPECT_NEAR(win.mean_diff, -0.05, 0.01);
  EXPECT_EQ(LowerVerdict(win), Verdict::kHolds);
  EXPECT_EQ(LowerVerdict(ComparePaired(worse, base, "loss")), Verdict::kDoesNotHold);
  const PairedTest tie = ComparePaired(same, base, "tie");
  EXPECT_LT(tie.ci_low, 0.0);
  EXPECT_GT(tie.ci_high, 0.0);
  EXPECT_EQ(LowerVerdict(tie), Verdict::kInconclusive);
}

TEST(PairedTest, IsDeterministicAndPairsOnlyCommonFiniteSeeds) {
  SeedValues a = Series(1.0, 0.2, 5), b = Series(1.2, 0.2, 6);
  const PairedTest t1 = ComparePaired(a, b, "same purpose"), t2 = ComparePaired(a, b, "same purpose");
  EXPECT_EQ(t1.ci_low, t2.ci_low);
  EXPECT_EQ(t1.ci_high, t2.ci_high);
  a[3] = PairedTest::kNaN;  // a failed run
  b.erase(7);               // a missing run
  EXPECT_EQ(ComparePaired(a, b, "p").pairs, 8u);
  const SeedValues two = {{1, 0.1}, {2, 0.2}};
  EXPECT_EQ(LowerVerdict(ComparePaired(two, {{1, 5.0}, {2, 6.0}}, "p")), Verdict::kInconclusive);
  EXPECT_EQ(LowerVerdict(CompareWithConstant(Series(0.05, 0.005, 7), 0.1, "c")), Verdict::kHolds);
}

}  // namespace
}  // namespace vigil::evaluation
