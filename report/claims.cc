#include "report/claims.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/format.h"
#include "report/paper_reference.h"
#include "report/result_table.h"

namespace vigil::report {

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

namespace {

// "min-max" of a column of the paper's table 3 or 4.
std::string PaperRange(const ResultTable& table, const std::string& column) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const std::string& row : table.rows) {
    lo = std::min(lo, TableValue(table, row, column));
    hi = std::max(hi, TableValue(table, row, column));
  }
  return FormatCell(lo, 2) + "-" + FormatCell(hi, 2);
}

// The paper's values of both sides of a claim (its tables 2-4, paper_reference.h), e.g. "0.06 < 18.05 m".
std::string PaperValues(const ClaimSpec& c) {
  if (c.metric == ClaimMetric::kReTrans)
    return PaperRange(PaperTable3(), c.method_a) + " < " + PaperRange(PaperTable3(), c.method_b) + " m";
  if (c.metric == ClaimMetric::kReYaw)
    return PaperRange(PaperTable4(), c.method_a) + " < " + PaperRange(PaperTable4(), c.method_b) + " deg";
  const ResultTable table2 = PaperTable2();
  const std::string a = FormatCell(TableValue(table2, c.method_a, c.group_a), 2);
  if (std::isfinite(c.constant_b)) return a + " m";
  return a + " < " + FormatCell(TableValue(table2, c.method_b, c.group_b), 2) + " m";
}

}  // namespace

std::vector<ClaimSpec> PaperClaims() {
  using M = ClaimMetric;
  const double kNaN = evaluation::PairedTest::kNaN;
  std::vector<ClaimSpec> claims = {
      {"a1", "original works at N(0,1): mean ATE below 0.1 m", "", M::kAte, "original", "noise_0_1", "", "",
       0.1},
      {"a2", "original degrades from N(0,1) to N(1,10)", "", M::kAte, "original", "noise_0_1", "original",
       "noise_1_10", kNaN},
      {"a3", "original degrades from N(1,10) to N(50,10)", "", M::kAte, "original", "noise_1_10", "original",
       "noise_50_10", kNaN},
      {"b1", "trunc improves on original at N(50,10)", "", M::kAte, "trunc", "noise_50_10", "original",
       "noise_50_10", kNaN},
      {"b2", "dtw improves on original at N(50,10)", "", M::kAte, "dtw", "noise_50_10", "original",
       "noise_50_10", kNaN},
      {"c1", "trunc beats dtw at N(0,1)", "", M::kAte, "trunc", "noise_0_1", "dtw", "noise_0_1", kNaN},
      {"c2", "trunc beats dtw at N(1,10)", "", M::kAte, "trunc", "noise_1_10", "dtw", "noise_1_10", kNaN},
      {"d1", "dtw beats trunc at N(50,10) (table 2)", "", M::kAte, "dtw", "noise_50_10", "trunc",
       "noise_50_10", kNaN},
      {"d2", "dtw has a lower relative translation error than trunc over all settings (table 3)", "",
       M::kReTrans, "dtw", "", "trunc", "", kNaN},
      {"d3", "dtw has a lower relative yaw error than trunc over all settings (table 4)", "", M::kReYaw,
       "dtw", "", "trunc", "", kNaN},
  };
  for (ClaimSpec& c : claims) c.paper = PaperValues(c);
  return claims;
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

}  // namespace vigil::report
