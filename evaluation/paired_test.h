// A paired comparison over seeds: the mean paired difference with a seeded bootstrap confidence interval, and
// the verdict it gives a claim "a is lower than b" (errors: lower is better).
//
// Pairs are the seeds present in both samples with finite values on both sides (a failed run has no value:
// its seed drops out of the comparison, and the caller reports how many did). The interval is the percentile
// bootstrap of the mean of the differences d_s = a_s - b_s: `resamples` resamples of the n pairs with
// replacement, drawn from Rng(seed, purpose), so the same data give the same interval everywhere. Verdict of
// "a < b": holds when the whole interval is below 0, does not hold when it is wholly above 0, inconclusive
// when it contains 0 or when there are fewer than `min_pairs` pairs (a percentile interval of 2 points says
// nothing).
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <string>

namespace vigil::evaluation {

using SeedValues = std::map<uint64_t, double>;  // seed -> value (one run's error)

struct PairedTestOptions {
  int resamples = 10000;
  double level = 0.95;
  int min_pairs = 3;
  uint64_t seed = 15;
};

struct PairedTest {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::size_t pairs = 0;
  double mean_a = kNaN, mean_b = kNaN;   // over the paired seeds
  double mean_diff = kNaN;               // mean of a - b
  double ci_low = kNaN, ci_high = kNaN;  // bootstrap interval of mean_diff
};

// `purpose` names the comparison (it seeds the bootstrap stream, so each claim has its own).
PairedTest ComparePaired(const SeedValues& a, const SeedValues& b, const std::string& purpose,
                         const PairedTestOptions& options = {});

// a compared with a constant b (e.g. "below 0.1 m"): every seed of a paired with `b`.
PairedTest CompareWithConstant(const SeedValues& a, double b, const std::string& purpose,
                               const PairedTestOptions& options = {});

enum class Verdict { kHolds, kDoesNotHold, kInconclusive };

// The verdict of "a < b" (see above).
Verdict LowerVerdict(const PairedTest& test, const PairedTestOptions& options = {});

const char* VerdictName(Verdict v);  // "holds", "does not hold", "inconclusive"

}  // namespace vigil::evaluation
