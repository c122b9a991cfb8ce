#include "experiments/claims.h"

#include <cmath>

#include "core/format.h"

namespace vigil::experiments {

const evaluation::SeedValues* SeedResults::Ate(const std::string& group, const std::string& method) const {
  const auto g = ate_m.find(group);
  if (g == ate_m.end()) return nullptr;
  const auto m = g->second.find(method);
  return m == g->second.end() ? nullptr : &m->second;
}

std::size_t SeedResults::Failed(const std::string& group, const std::string& method) const {
  const auto g = failed.find(group);
  if (g == failed.end()) return 0;
  const auto m = g->second.find(method);
  return m == g->second.end() ? 0 : m->second;
}

std::vector<ClaimSpec> PaperClaims() {
  using M = ClaimMetric;
  const double kNaN = evaluation::PairedTest::kNaN;
  return {
      {"a1", "original works at N(0,1): mean ATE below 0.1 m", "0.06 m", M::kAte, "original", "noise_0_1", "",
       "", 0.1},
      {"a2", "original degrades from N(0,1) to N(1,10)", "0.06 < 0.15 m", M::kAte, "original", "noise_0_1",
       "original", "noise_1_10", kNaN},
      {"a3", "original degrades from N(1,10) to N(50,10)", "0.15 < 18.05 m", M::kAte, "original",
       "noise_1_10", "original", "noise_50_10", kNaN},
      {"b1", "trunc improves on original at N(50,10)", "0.32 < 18.05 m", M::kAte, "trunc", "noise_50_10",
       "original", "noise_50_10", kNaN},
      {"b2", "dtw improves on original at N(50,10)", "0.06 < 18.05 m", M::kAte, "dtw", "noise_50_10",
       "original", "noise_50_10", kNaN},
      {"c1", "trunc beats dtw at N(0,1)", "0.04 < 0.06 m", M::kAte, "trunc", "noise_0_1", "dtw", "noise_0_1",
       kNaN},
      {"c2", "trunc beats dtw at N(1,10)", "0.14 < 0.15 m", M::kAte, "trunc", "noise_1_10", "dtw",
       "noise_1_10", kNaN},
      {"d1", "dtw beats trunc at N(50,10) (table 2)", "0.06 < 0.32 m", M::kAte, "dtw", "noise_50_10", "trunc",
       "noise_50_10", kNaN},
      {"d2", "dtw has a lower relative translation error than trunc over all settings (table 3)",
       "0.07-0.20 < 0.16-0.51 m", M::kReTrans, "dtw", "", "trunc", "", kNaN},
      {"d3", "dtw has a lower relative yaw error than trunc over all settings (table 4)",
       "0.08-0.10 < 0.49-0.61 deg", M::kReYaw, "dtw", "", "trunc", "", kNaN},
  };
}

namespace {

const evaluation::SeedValues* Side(const ClaimSpec& c, const SeedResults& r, bool a) {
  const std::string& method = a ? c.method_a : c.method_b;
  switch (c.metric) {
    case ClaimMetric::kAte:
      return r.Ate(a ? c.group_a : c.group_b, method);
    case ClaimMetric::kReTrans: {
      const auto it = r.re_trans_m.find(method);
      return it == r.re_trans_m.end() ? nullptr : &it->second;
    }
    case ClaimMetric::kReYaw: {
      const auto it = r.re_yaw_deg.find(method);
      return it == r.re_yaw_deg.end() ? nullptr : &it->second;
    }
  }
  return nullptr;
}

}  // namespace

ClaimResult EvaluateClaim(const ClaimSpec& claim, const SeedResults& results,
                          const evaluation::PairedTestOptions& options) {
  ClaimResult r;
  r.spec = claim;
  const bool constant = std::isfinite(claim.constant_b);
  const evaluation::SeedValues* a = Side(claim, results, true);
  const evaluation::SeedValues* b = constant ? nullptr : Side(claim, results, false);
  r.available = a != nullptr && (constant || b != nullptr);
  if (!r.available) return r;
  const std::string purpose = claim.id + ": " + SideLabel(claim, true) + " < " + SideLabel(claim, false);
  r.test = constant ? evaluation::CompareWithConstant(*a, claim.constant_b, purpose, options)
                    : evaluation::ComparePaired(*a, *b, purpose, options);
  r.verdict = evaluation::LowerVerdict(r.test, options);
  if (claim.metric == ClaimMetric::kAte) {
    r.failed_a = results.Failed(claim.group_a, claim.method_a);
    if (!constant) r.failed_b = results.Failed(claim.group_b, claim.method_b);
  }
  return r;
}

ClaimSpec RenameMethods(ClaimSpec claim, const std::map<std::string, std::string>& rename, bool* changed) {
  *changed = false;
  for (std::string* m : {&claim.method_a, &claim.method_b}) {
    const auto it = rename.find(*m);
    if (it == rename.end()) continue;
    *m = it->second;
    *changed = true;
  }
  return claim;
}

std::string SideLabel(const ClaimSpec& claim, bool a) {
  if (!a && std::isfinite(claim.constant_b)) return FormatDouble(claim.constant_b);
  const std::string& method = a ? claim.method_a : claim.method_b;
  if (claim.metric != ClaimMetric::kAte) return method + " (pooled)";
  return method + " @ " + (a ? claim.group_a : claim.group_b);
}

}  // namespace vigil::experiments
