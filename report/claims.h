// The claims the paper (Long et al., IFAC 2020) makes about its simulation, and their evaluation on per-seed
// results of a sweep: each claim is "A has a lower error than B", tested over seeds with ComparePaired
// (paired_test.h). Kept apart from the sweep files so that it can be tested on synthetic results.
//
// Claims (the paper's numbers, tables 2-4 of paper_reference.h, in each claim's `paper` text):
//   a1 original works at N(0,1): its mean ATE is below 0.1 m (paper 0.06 m);
//   a2, a3 original degrades as the glitches grow: noise_0_1 < noise_1_10 < noise_50_10;
//   b1, b2 both methods improve on original at large glitches (noise_50_10);
//   c1, c2 the threshold method beats DTW at small glitches (noise_0_1, noise_1_10);
//   d1 DTW is best at N(50,10) (table 2: below trunc there; below original is b2);
//   d2, d3 DTW has lower relative translation / yaw errors than trunc over all settings (tables 3, 4).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "evaluation/paired_test.h"

namespace vigil::report {

// Per-seed results of a sweep, by the names of its groups (table 2 columns) and methods.
struct SeedResults {
  std::map<std::string, std::map<std::string, evaluation::SeedValues>>
      ate_m;  // group -> method -> ATE RMSE [m]
  // method -> relative error of each seed, pooled over every group and distance (a seed counts only when
  // every group's run of that seed succeeded).
  std::map<std::string, evaluation::SeedValues> re_trans_m, re_yaw_deg;
  std::map<std::string, std::map<std::string, std::size_t>> failed;  // group -> method -> failed runs

  const evaluation::SeedValues* Ate(const std::string& group, const std::string& method) const;
  std::size_t Failed(const std::string& group, const std::string& method) const;
};

enum class ClaimMetric { kAte, kReTrans, kReYaw };

// "a < b": a (method_a in group_a) has a lower error than b (method_b in group_b, or the constant).
struct ClaimSpec {
  std::string id, text, paper;
  ClaimMetric metric = ClaimMetric::kAte;
  std::string method_a, group_a, method_b, group_b;  // groups unused for relative errors
  double constant_b = evaluation::PairedTest::kNaN;  // finite: b is this constant
};

std::vector<ClaimSpec> PaperClaims();

struct ClaimResult {
  ClaimSpec spec;
  bool available = false;  // both sides exist in the results
  evaluation::PairedTest test;
  evaluation::Verdict verdict = evaluation::Verdict::kInconclusive;
  std::size_t failed_a = 0, failed_b = 0;  // failed runs on each side (ATE claims)
};

ClaimResult EvaluateClaim(const ClaimSpec& claim, const SeedResults& results,
                          const evaluation::PairedTestOptions& options = {});

// The claim with its methods renamed (e.g. trunc -> relative_threshold); `changed` tells whether any was.
ClaimSpec RenameMethods(ClaimSpec claim, const std::map<std::string, std::string>& rename, bool* changed);

// "original @ noise_50_10", "dtw (pooled)" or "0.1".
std::string SideLabel(const ClaimSpec& claim, bool a);

}  // namespace vigil::report
