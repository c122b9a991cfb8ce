#include "detectors/dtw_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/random.h"
#include "detectors/dtw_kernel.h"
#include "detectors/dtw_matcher.h"

namespace vigil::detectors {
namespace {

std::vector<double> Random(std::size_t n, Rng& rng, double scale = 1.0) {
  std::vector<double> v(n);
  for (double& x : v) x = scale * rng.Normal();
  return v;
}

// Textbook DTW over the full (n + 1) x (m + 1) matrix with an infinite border, written independently of
// Algorithm 1's rolling row.
double FullMatrixDtw(const std::vector<double>& a, int n, const std::vector<double>& b, int m, int d) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> D(n + 1, std::vector<double>(m + 1, inf));
  D[0][0] = 0.0;
  for (int j = 1; j <= n; ++j) {
    for (int i = 1; i <= m; ++i) {
      double cost = 0.0;
      for (int c = 0; c < d; ++c) cost += std::pow(a[(j - 1) * d + c] - b[(i - 1) * d + c], 2);
      D[j][i] = cost + std::min({D[j - 1][i - 1], D[j - 1][i], D[j][i - 1]});
    }
  }
  return D[n][m];
}

TEST(DtwDistance, Algorithm1EqualsFullMatrixOnRandomInputs) {
  Rng rng(7, "dtw_test");
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + static_cast<int>(rng.UniformIndex(30)), m = 1 + static_cast<int>(rng.UniformIndex(50));
    const int d = 1 + static_cast<int>(rng.UniformIndex(6));
    const auto a = Random(n * d, rng), b = Random(m * d, rng);
    const double full = FullMatrixDtw(a, n, b, m, d);
    EXPECT_NEAR(DtwDistance(a.data(), n, b.data(), m, d), full, 1e-12 * full) << n << " " << m << " " << d;
    EXPECT_NEAR(DtwAlign(a.data(), n, b.data(), m, d).distance, full, 1e-12 * full);
  }
}

TEST(DtwDistance, KnownAnswers) {
  // Identical series: 0.
  const std::vector<double> x = {0.0, 1.0, 3.0, 2.0, -1.0, 0.5};
  EXPECT_EQ(DtwDistance(x.data(), 6, x.data(), 6, 1), 0.0);
  // A copy with repeated samples (time-warped) is still at distance 0.
  const std::vector<double> warped = {0.0, 0.0, 1.0, 3.0, 3.0, 3.0, 2.0, -1.0, 0.5, 0.5};
  EXPECT_EQ(DtwDistance(x.data(), 6, warped.data(), 10, 1), 0.0);
  // A copy shifted by one sample: only the end points cost, |x0 - x1|^2 at the start ... the best path pays
  // (0 - 1)^2 once when the copy starts one sample late and drops the first value.
  const std::vector<double> shifted = {1.0, 3.0, 2.0, -1.0, 0.5, 0.5};
  EXPECT_DOUBLE_EQ(DtwDistance(x.data(), 6, shifted.data(), 6, 1), 1.0);
  // Constant series offset by delta: every cell costs delta^2 and the shortest path has max(n, m) cells.
  const std::vector<double> zeros(4 * 2, 0.0), offset(7 * 2, 0.5);
  EXPECT_DOUBLE_EQ(DtwDistance(zeros.data(), 4, offset.data(), 7, 2), 7 * 2 * 0.25);
  // Squared Euclidean cell cost without square root: one 2-D row at distance (3, 4) costs 25.
  const std::vector<double> p = {0.0, 0.0}, q = {3.0, 4.0};
  EXPECT_DOUBLE_EQ(DtwDistance(p.data(), 1, q.data(), 1, 2), 25.0);
}

TEST(DtwDistance, AlignmentPathIsValidAndCostsTheDistance) {
  Rng rng(3, "dtw_align");
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 1 + static_cast<int>(rng.UniformIndex(12)), m = 1 + static_cast<int>(rng.UniformIndex(40));
    const int d = 3;
    const auto a = Random(n * d, rng), b = Random(m * d, rng);
    const DtwAlignment al = DtwAlign(a.data(), n, b.data(), m, d);
    ASSERT_FALSE(al.path.empty());
    EXPECT_EQ(al.path.front(), std::make_pair(0, 0));
    EXPECT_EQ(al.path.back(), std::make_pair(n - 1, m - 1));
    double cost = SquaredDistance(a.data(), b.data(), d);
    for (std::size_t s = 1; s < al.path.size(); ++s) {
      const int dj = al.path[s].first - al.path[s - 1].first, di = al.path[s].second - al.path[s - 1].second;
      EXPECT_TRUE((dj == 1 && di == 0) || (dj == 0 && di == 1) || (dj == 1 && di == 1));
      cost += SquaredDistance(a.data() + al.path[s].first * d, b.data() + al.path[s].second * d, d);
    }
    EXPECT_NEAR(cost, al.distance, 1e-9 * al.distance);
  }
}

// The production matcher (whatever kernel this CPU selects) against the double reference.
void ExpectMatcherEqualsReference(int k, int n, int m, int d, uint64_t seed) {
  Rng rng(seed, "matcher");
  const auto templates = Random(static_cast<std::size_t>(k) * n * d, rng);
  const auto slice = Random(static_cast<std::size_t>(m) * d, rng, 1.5);
  const std::vector<float> slice_f(slice.begin(), slice.end());
  DtwMatcher matcher(templates.data(), k, n, d);
  std::vector<float> fast(k);
  matcher.Distances(slice_f.data(), m, fast.data());
  int best = 0;
  std::vector<double> reference(k);
  for (int t = 0; t < k; ++t) {
    reference[t] = DtwDistance(templates.data() + static_cast<std::size_t>(t) * n * d, n, slice.data(), m, d);
    EXPECT_NEAR(fast[t], reference[t], 1e-4 * reference[t]) << "template " << t << " k=" << k << " d=" << d;
    if (reference[t] < reference[best]) best = t;
  }
  const DtwMatch match = matcher.Best(slice_f.data(), m);
  EXPECT_NEAR(match.distance, reference[best], 1e-4 * reference[best]);
  EXPECT_NEAR(reference[match.index], reference[best], 1e-4 * reference[best]);
}

TEST(DtwMatcher, EqualsReferenceOnThePaperGeometries) {
  ExpectMatcherEqualsReference(10, 40, 40, 3, 1);  // real robot
  ExpectMatcherEqualsReference(10, 10, 40, 6, 2);  // simulation
}

TEST(DtwMatcher, EqualsReferenceForAnyCountLengthAndDimension) {
  for (int k : {1, 7, 8, 9, 16, 17, 33})
    for (int d = 1; d <= 6; ++d)
      ExpectMatcherEqualsReference(k, 1 + (k * 5 + d) % 23, 3 + (k + 7 * d) % 45, d, k * 10 + d);
}

TEST(DtwMatcher, EveryKernelEqualsReference) {
  // Both instruction-set variants directly, not only the one this CPU selects.
  std::vector<internal::DtwKernel> kernels = {internal::GenericDtwKernel()};
#ifdef VIGIL_DTW_AVX2_KERNEL
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    kernels.push_back(internal::Avx2DtwKernel());
#endif
  Rng rng(11, "kernels");
  const int n = 10, m = 40, d = 6, groups = 2;
  const auto templates = Random(16 * n * d, rng), slice = Random(m * d, rng);
  const std::vector<float> slice_f(slice.begin(), slice.end());
  std::vector<internal::Lane8> packed(groups * n * d), row((m + 1) * 2), out(2);
  for (int t = 0; t < 16; ++t)
    for (int j = 0; j < n; ++j)
      for (int c = 0; c < d; ++c)
        packed[((t / 8) * n + j) * d + c].v[t % 8] = static_cast<float>(templates[(t * n + j) * d + c]);
  for (internal::DtwKernel kernel : kernels) {
    internal::DtwKernelArgs args{packed.data(), groups, n, d, slice_f.data(), m, row.data(), out.data()};
    kernel(args);
    for (int t = 0; t < 16; ++t) {
      const double reference = DtwDistance(templates.data() + t * n * d, n, slice.data(), m, d);
      EXPECT_NEAR(out[t / 8].v[t % 8], reference, 1e-4 * reference);
    }
  }
}

TEST(DtwMatcher, RejectsUnsupportedDimensions) {
  const std::vector<double> t(7 * 2, 0.0);
  EXPECT_THROW(DtwMatcher(t.data(), 1, 2, 7), std::invalid_argument);
  EXPECT_THROW(DtwMatcher(t.data(), 0, 2, 3), std::invalid_argument);
}

}  // namespace
}  // namespace vigil::detectors
