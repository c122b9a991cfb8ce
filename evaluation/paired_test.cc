#include "evaluation/paired_test.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/random.h"

namespace vigil::evaluation {
namespace {

// Nearest-rank-free percentile: linear interpolation between order statistics of sorted `v`.
double Percentile(const std::vector<double>& v, double p) {
  const double pos = p * static_cast<double>(v.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

PairedTest FromPairs(const std::vector<double>& a, const std::vector<double>& b, const std::string& purpose,
                     const PairedTestOptions& options) {
  PairedTest t;
  t.pairs = a.size();
  if (a.empty()) return t;
  const double n = static_cast<double>(a.size());
  std::vector<double> d(a.size());
  double sa = 0, sb = 0, sd = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d[i] = a[i] - b[i];
    sa += a[i];
    sb += b[i];
    sd += d[i];
  }
  t.mean_a = sa / n;
  t.mean_b = sb / n;
  t.mean_diff = sd / n;
  Rng rng(options.seed, "paired bootstrap: " + purpose);
  std::vector<double> means(static_cast<std::size_t>(std::max(1, options.resamples)));
  for (double& m : means) {
    double s = 0;
    for (std::size_t i = 0; i < d.size(); ++i) s += d[rng.UniformIndex(d.size())];
    m = s / n;
  }
  std::sort(means.begin(), means.end());
  const double tail = 0.5 * (1.0 - options.level);
  t.ci_low = Percentile(means, tail);
  t.ci_high = Percentile(means, 1.0 - tail);
  return t;
}

}  // namespace

PairedTest ComparePaired(const SeedValues& a, const SeedValues& b, const std::string& purpose,
                         const PairedTestOptions& options) {
  std::vector<double> va, vb;
  for (const auto& [seed, value] : a) {
    const auto it = b.find(seed);
    if (it == b.end() || !std::isfinite(value) || !std::isfinite(it->second)) continue;
    va.push_back(value);
    vb.push_back(it->second);
  }
  return FromPairs(va, vb, purpose, options);
}

PairedTest CompareWithConstant(const SeedValues& a, double b, const std::string& purpose,
                               const PairedTestOptions& options) {
  SeedValues constant;
  for (const auto& [seed, value] : a) constant[seed] = b;
  return ComparePaired(a, constant, purpose, options);
}

Verdict LowerVerdict(const PairedTest& test, const PairedTestOptions& options) {
  if (test.pairs < static_cast<std::size_t>(options.min_pairs) || !std::isfinite(test.ci_low) ||
      !std::isfinite(test.ci_high))
    return Verdict::kInconclusive;
  if (test.ci_high < 0.0) return Verdict::kHolds;
  if (test.ci_low > 0.0) return Verdict::kDoesNotHold;
  return Verdict::kInconclusive;
}

const char* VerdictName(Verdict v) {
  switch (v) {
    case Verdict::kHolds:
      return "holds";
    case Verdict::kDoesNotHold:
      return "does not hold";
    case Verdict::kInconclusive:
      break;
  }
  return "inconclusive";
}

}  // namespace vigil::evaluation
