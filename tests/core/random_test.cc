#include "core/random.h"

#include <cmath>

#include <gtest/gtest.h>

namespace vigil {
namespace {

TEST(Random, SameSeedAndPurposeGiveTheSameStream) {
  Rng a(7, "imu_noise"), b(7, "imu_noise");
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.NextU64(), b.NextU64());
}

TEST(Random, PurposesAndSeedsGiveDifferentStreams) {
  Rng a(7, "imu_noise"), b(7, "glitch"), c(8, "imu_noise");
  int same_ab = 0, same_ac = 0;
  for (int i = 0; i < 100; ++i) {
    const uint64_t x = a.NextU64();
    same_ab += x == b.NextU64();
    same_ac += x == c.NextU64();
  }
  EXPECT_EQ(same_ab, 0);
  EXPECT_EQ(same_ac, 0);
}

TEST(Random, KnownValuesPinThePlatformIndependentStream) {
  // The stream is part of the reproducibility contract: a change here changes every dataset.
  // Values recorded from this implementation (xoshiro256** seeded by SplitMix64 over FNV-1a of the purpose).
  Rng rng(1, "test");
  EXPECT_EQ(rng.NextU64(), 8564616605146314750ull);
  EXPECT_DOUBLE_EQ(rng.Normal(), 0.94810948112546189);
}

TEST(Random, NormalHasUnitMomentsAndUniformIsInRange) {
  Rng rng(3, "moments");
  const int n = 200000;
  double sum = 0.0, sum2 = 0.0, sum4 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.Normal();
    sum += x;
    sum2 += x * x;
    sum4 += x * x * x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(sum2 / n, 1.0, 0.01);
  EXPECT_NEAR(sum4 / n, 3.0, 0.06);
  for (int i = 0; i < 1000; ++i) {
    const double u = rng.Uniform();
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
    EXPECT_LT(rng.UniformIndex(7), 7u);
  }
}

}  // namespace
}  // namespace vigil
