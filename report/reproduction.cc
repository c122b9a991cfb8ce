#include "report/reproduction.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "core/format.h"
#include "core/output.h"
#include "evaluation/statistics.h"
#include "experiments/sweeps/sweep_aggregate.h"
#include "experiments/sweeps/sweep_engine.h"
#include "report/paper_reference.h"
#include "report/result_table.h"
#include "report/tables.h"

namespace vigil::report {
namespace fs = std::filesystem;
namespace {

const char* const kGroups[] = {"noise_0_1", "noise_1_10", "noise_50_10"};
const char* const kPaperMethods[] = {"trunc", "dtw", "original"};
constexpr const char* kNoiseAblationDir = "noise_ablation";
// The cell of table 2 where the paper's original collapses, and vigil's bound for a collapse of the paper's
// order of magnitude.
constexpr const char* kCollapseGroup = "noise_50_10";
constexpr const char* kCollapseMethod = "original";
constexpr double kCollapseThreshold_m = 6.0;
// The glitch rate of vigil's paper sweep (configs/paper_sweep.yaml; the paper says "a few samples").
constexpr double kSweepGlitchRate = 0.01;

// Claim id -> the ablations under which it holds.
using HoldsWith = std::map<std::string, std::vector<std::string>>;

// Per (method, seed): relative errors summed over groups and distances.
struct PooledRe {
  double trans = 0, yaw = 0, n = 0;
  std::size_t groups_ok = 0;
};

std::string Interval(const evaluation::PairedTest& t) {
  return FormatCell(t.mean_diff) + " [" + FormatCell(t.ci_low) + ", " + FormatCell(t.ci_high) + "]";
}

bool HasMethod(const SeedResults& r, const std::string& method) {
  for (const auto& [group, methods] : r.ate_m)
    if (methods.count(method)) return true;
  return false;
}

std::string ClaimRow(const ClaimResult& c, const std::string& label) {
  if (!c.available)
    return "| " + label + " | " + c.spec.text + " | " + c.spec.paper + " | n/a | n/a | 0 | n/a |\n";
  std::string failures;
  if (c.failed_a + c.failed_b > 0)
    failures =
        " (failed runs left out: " + std::to_string(c.failed_a) + " / " + std::to_string(c.failed_b) + ")";
  return "| " + label + " | " + c.spec.text + " | " + c.spec.paper + " | " + SideLabel(c.spec, true) + " " +
         FormatCell(c.test.mean_a) + " vs " + SideLabel(c.spec, false) + " " + FormatCell(c.test.mean_b) +
         " | " + Interval(c.test) + " | " + std::to_string(c.test.pairs) + failures + " | **" +
         evaluation::VerdictName(c.verdict) + "** |\n";
}

const char* kClaimHeader =
    "| claim | statement (A < B) | paper | this sweep: A vs B (means) | mean of A - B [95 % CI] | pairs | "
    "verdict |\n|---|---|---|---|---|---|---|\n";

// The method variants of the ablation: label -> renaming.
std::vector<std::pair<std::string, std::map<std::string, std::string>>> Variants(const SeedResults& r) {
  std::vector<std::pair<std::string, std::map<std::string, std::string>>> out;
  const bool rel = HasMethod(r, "relative_threshold"), norm = HasMethod(r, "normalized_dtw");
  if (rel) out.push_back({"trunc -> relative_threshold", {{"trunc", "relative_threshold"}}});
  if (norm) out.push_back({"dtw -> normalized_dtw", {{"dtw", "normalized_dtw"}}});
  if (rel && norm) out.push_back({"both", {{"trunc", "relative_threshold"}, {"dtw", "normalized_dtw"}}});
  return out;
}

ResultTable AteTable(const SeedResults& r, const std::vector<std::string>& methods,
                     const std::string& title) {
  ResultTable t;
  t.title = title;
  t.corner = "method";
  t.rows = methods;
  for (const char* g : kGroups) t.columns.push_back(g);
  t.decimals = 2;
  for (const std::string& m : methods) {
    std::vector<double> row;
    for (const char* g : kGroups) {
      const evaluation::SeedValues* v = r.Ate(g, m);
      std::vector<double> values;
      if (v)
        for (const auto& [seed, x] : *v)
          if (std::isfinite(x)) values.push_back(x);
      row.push_back(evaluation::ComputeStatistics(values).mean);
    }
    t.values.push_back(row);
  }
  return t;
}

std::string FailureNote(const SeedResults& r, const std::vector<std::string>& methods) {
  std::string s;
  for (const char* g : kGroups)
    for (const std::string& m : methods)
      if (const std::size_t f = r.Failed(g, m); f > 0)
        s += (s.empty() ? "" : ", ") + m + " @ " + g + ": " + std::to_string(f);
  return s.empty() ? "no failed run" : "failed runs (left out of the means): " + s;
}

}  // namespace

SeedResults ReadSeedResults(const fs::path& dir, const experiments::SweepSpec& spec) {
  SeedResults out;
  const std::vector<double> distances = experiments::SweepDistances(spec);
  std::map<std::string, std::map<uint64_t, PooledRe>> pooled;
  std::set<std::string> groups;
  experiments::AggregateSweep(
      dir, spec, distances,
      [&](const experiments::SweepRunRef& run, const experiments::SweepCell& cell, const nlohmann::json* m) {
        const std::string group = experiments::CellGroupLabel(spec, cell),
                          method = spec.methods[cell.method].label;
        groups.insert(group);
        out.ate_m[group][method];  // the cell exists even when no run of it succeeded
        if (!m) return;
        experiments::CellResult one;
        experiments::AddRunMetrics(*m, distances, &one);
        if (one.failed > 0) {
          ++out.failed[group][method];
          return;
        }
        if (!one.ate_rmse_m.empty()) out.ate_m[group][method][run.seed] = one.ate_rmse_m.front();
        PooledRe& p = pooled[method][run.seed];
        for (std::size_t d = 0; d < distances.size(); ++d) {
          p.trans += one.re_trans_weighted[d];
          p.yaw += one.re_yaw_weighted[d];
          p.n += one.re_n[d];
        }
        ++p.groups_ok;
      });
  for (const auto& [method, seeds] : pooled)
    for (const auto& [seed, p] : seeds) {
      if (p.groups_ok != groups.size() || !(p.n > 0)) continue;
      out.re_trans_m[method][seed] = p.trans / p.n;
      out.re_yaw_deg[method][seed] = p.yaw / p.n;
    }
  return out;
}

std::map<std::string, SeedResults> SplitByLastGroupLabel(const SeedResults& results) {
  std::map<std::string, SeedResults> out;
  for (const auto& [group, methods] : results.ate_m) {
    const std::size_t dash = group.rfind('-');
    if (dash == std::string::npos) continue;
    SeedResults& r = out[group.substr(dash + 1)];
    r.ate_m[group.substr(0, dash)] = methods;
    const auto f = results.failed.find(group);
    if (f != results.failed.end()) r.failed[group.substr(0, dash)] = f->second;
  }
  return out;
}

bool HasPaperGrid(const SeedResults& results) {
  for (const char* g : kGroups)
    for (const char* m : kPaperMethods)
      if (!results.Ate(g, m)) return false;
  return true;
}

namespace {

// The opening: the sweep, the methods, and how a claim is tested.
std::string IntroductionSection(const std::string& sweep, std::size_t seeds,
                                const evaluation::PairedTestOptions& options) {
  std::string s = "# Reproduction of the paper's simulation claims\n\n";
  s += "Sweep `" + sweep + "`, " + std::to_string(seeds) +
       " seeds per cell. Rows `trunc`, `dtw`, `original` are the paper's methods (threshold on the measured "
       "value with clamping; DTW on raw slices replaced by the best template; no detection).\n\n";
  s += "Test: each claim says A has a lower error than B. Per seed, d = A - B (runs of the same seed share "
       "their simulated recording); the interval is the " +
       FormatCell(100 * options.level, 0) + " % percentile bootstrap interval of the mean of d (" +
       std::to_string(options.resamples) +
       " resamples of the seeds, seeded, so it is the same on every machine). Verdict: **holds** when the "
       "whole interval is below 0, **does not hold** when it is wholly above 0, **inconclusive** when it "
       "contains 0 (or fewer than " +
       std::to_string(options.min_pairs) +
       " pairs). A failed run has no error: its seed is left out of the pair. ATE = translation RMSE [m] "
       "after posyaw alignment; relative errors are pooled per seed over every glitch setting and distance "
       "(7-35 m).\n\n";
  return s;
}

// Every claim of the paper on the sweep under the heading `title`; `*main` receives their results.
std::string ClaimsSection(const std::string& title, const SeedResults& results,
                          const evaluation::PairedTestOptions& options, std::vector<ClaimResult>* main) {
  std::string s = "## " + title + "\n\n" + std::string(kClaimHeader);
  for (const ClaimSpec& c : PaperClaims()) {
    main->push_back(EvaluateClaim(c, results, options));
    s += ClaimRow(main->back(), c.id);
  }
  return s + "\n" + FailureNote(results, {"trunc", "dtw", "original"}) + ".\n\n";
}

// Ablation 1: every claim again with vigil's variants of the methods (empty when the sweep has none), under
// the heading `title`.
std::string VariantsSection(const std::string& title, const SeedResults& results,
                            const evaluation::PairedTestOptions& options, HoldsWith* holds_with) {
  const auto variants = Variants(results);
  if (variants.empty()) return "";
  std::string s = "## " + title + "\n\n";
  s += "Every claim that names trunc or dtw again with vigil's variant in its place (`relative_threshold`: "
       "bound on |value - mean of the last 4 normal values|; `normalized_dtw`: slices compared after "
       "removing a robust per-channel line, replaced by the template's shape on the slice's line).\n\n";
  s += "| claim | variant | A vs B (means) | mean of A - B [95 % CI] | pairs | verdict |\n"
       "|---|---|---|---|---|---|\n";
  for (const ClaimSpec& c : PaperClaims())
    for (const auto& [label, rename] : variants) {
      bool changed = false;
      const ClaimSpec v = RenameMethods(c, rename, &changed);
      if (!changed) continue;
      const ClaimResult r = EvaluateClaim(v, results, options);
      if (r.verdict == evaluation::Verdict::kHolds) (*holds_with)[c.id].push_back(label);
      s += "| " + c.id + " | " + label + " | " + SideLabel(v, true) + " " + FormatCell(r.test.mean_a) +
           " vs " + SideLabel(v, false) + " " + FormatCell(r.test.mean_b) + " | " + Interval(r.test) + " | " +
           std::to_string(r.test.pairs) + " | " + evaluation::VerdictName(r.verdict) + " |\n";
    }
  s += "\n";
  std::vector<std::string> extra = {"trunc", "relative_threshold", "dtw", "normalized_dtw", "original"};
  if (HasMethod(results, "hampel")) extra.push_back("hampel");
  return s +
         SideBySideMarkdown(
             AteTable(results, extra, "Table 2 with every method: ATE RMSE [m], mean over seeds"),
             PaperTable2()) +
         "\n";
}

// Mean, max, ... of the ATE of (group, method) over its finite seeds.
evaluation::ErrorStatistics MeanAte(const SeedResults& r, const std::string& group,
                                    const std::string& method) {
  const evaluation::SeedValues* v = r.Ate(group, method);
  std::vector<double> values;
  if (v)
    for (const auto& [seed, x] : *v)
      if (std::isfinite(x)) values.push_back(x);
  return evaluation::ComputeStatistics(values);
}

// The largest cell of table 2 other than original at noise_50_10, the paper's collapsed cell.
template <class CellValue>
double LargestOtherCell(CellValue value) {
  double other = 0.0;
  for (const char* g : kGroups)
    for (const char* m : kPaperMethods)
      if (std::string(g) != kCollapseGroup || std::string(m) != kCollapseMethod)
        other = std::max(other, value(g, m));
  return other;
}

// Whether each noise model reproduces the paper's collapse of original at N(50,10) and nothing else.
std::string CollapseTable(const SeedResults& results,
                          const std::map<std::string, SeedResults>& noise_models) {
  const ResultTable paper = PaperTable2();
  const double paper_collapse_m = TableValue(paper, kCollapseMethod, kCollapseGroup);
  const double paper_other_m =
      LargestOtherCell([&](const char* g, const char* m) { return TableValue(paper, m, g); });
  std::string s = "\nThe paper's collapse: original at N(50,10) reaches " + FormatCell(paper_collapse_m, 2) +
                  " m, while every other cell of its table 2 is at most " + FormatCell(paper_other_m, 2) +
                  " m.\n\n";
  s += "| noise model | original @ noise_50_10: mean ATE [m] | max [m] | failed runs | collapse of the "
       "paper's order of magnitude (>= " +
       FormatDouble(kCollapseThreshold_m) +
       " m) | largest other cell of table 2 [m] | other cells as the "
       "paper's (<= " +
       FormatCell(paper_other_m, 2) + " m) |\n|---|---|---|---|---|---|---|\n";
  const auto collapse_row = [&](const std::string& model, const SeedResults& r) {
    const evaluation::ErrorStatistics st = MeanAte(r, kCollapseGroup, kCollapseMethod);
    const double other =
        LargestOtherCell([&](const char* g, const char* m) { return MeanAte(r, g, m).mean; });
    s += "| " + model + " | " + FormatCell(st.mean, 2) + " | " + FormatCell(st.max, 2) + " | " +
         std::to_string(r.Failed(kCollapseGroup, kCollapseMethod)) + " | " +
         (st.mean >= kCollapseThreshold_m ? "yes" : "no") + " | " + FormatCell(other, 2) + " | " +
         (other <= paper_other_m ? "yes" : "no") + " |\n";
  };
  collapse_row("matched", results);
  for (const auto& [model, r] : noise_models) collapse_row(model, r);
  return s + "\n";
}

// Ablation 2: the estimator's IMU noise model (empty without the noise ablation sweep).
std::string NoiseModelSection(const SeedResults& results,
                              const std::map<std::string, SeedResults>& noise_models,
                              const evaluation::PairedTestOptions& options, HoldsWith* holds_with) {
  if (noise_models.empty()) return "";
  std::string s = "## Ablation: the estimator's IMU noise model\n\n";
  s += "The paper's methods with the estimator's IMU noise mis-set (`estimator.imu_noise.model`): "
       "`densities_as_per_sample` = the sensor's densities typed in as per-sample values (white noise "
       "believed sqrt(200) = 14 x smaller), `vins_euroc` = VINS-Mono's EuRoC acc_n 0.08, gyr_n 0.004, acc_w "
       "4e-5, gyr_w 2e-6 per sample. `matched` = the main sweep (the sensor's own densities, all its "
       "seeds). The ablation sweep has its own, fewer seeds (`vigil paper` runs "
       "configs/paper_noise_sweep.yaml "
       "with at most 5, to keep its wall time short: the pairs column of each claim counts them). Paper "
       "values in parentheses.\n\n";
  const std::vector<std::string> methods = {"trunc", "dtw", "original"};
  s += SideBySideMarkdown(AteTable(results, methods, "matched: ATE RMSE [m]"), PaperTable2()) + "\n" +
       FailureNote(results, methods) + ".\n\n";
  for (const auto& [model, r] : noise_models) {
    s += SideBySideMarkdown(AteTable(r, methods, model + ": ATE RMSE [m]"), PaperTable2()) + "\n" +
         FailureNote(r, methods) + ".\n\n";
  }
  s += "| claim | ";
  for (const auto& [model, r] : noise_models) s += model + " (mean of A - B [95 % CI], verdict) | ";
  s += "\n|---|";
  for (std::size_t i = 0; i < noise_models.size(); ++i) s += "---|";
  s += "\n";
  for (const ClaimSpec& c : PaperClaims()) {
    if (c.metric != ClaimMetric::kAte) continue;  // the ablation sweep is small: table 2 claims only
    s += "| " + c.id + " |";
    for (const auto& [model, r] : noise_models) {
      const ClaimResult cr = EvaluateClaim(c, r, options);
      if (cr.verdict == evaluation::Verdict::kHolds) (*holds_with)[c.id].push_back("noise model " + model);
      s += " " + Interval(cr.test) + ", " + evaluation::VerdictName(cr.verdict) + " (" +
           std::to_string(cr.test.pairs) + " pairs) |";
    }
    s += "\n";
  }
  return s + CollapseTable(results, noise_models);
}

// Why DTW differs from the paper's: the share of the paper's slices that hold a glitch.
std::string RawDtwExplanation() {
  const double clean = 1.0 - kSweepGlitchRate;
  const double with_glitch = 1.0 - std::pow(clean, kPaperSliceLength);
  return " The difference from the paper that explains it: the paper's DTW compares raw slices and writes "
         "the raw best template over the slice, so the motion of another part of the trajectory replaces "
         "the robot's own in every flagged slice (at glitch rate " +
         FormatDouble(kSweepGlitchRate) + " and M = " + std::to_string(kPaperSliceLength) + ", 1 - " +
         FormatDouble(clean) + "^" + std::to_string(kPaperSliceLength) + " = " +
         FormatCell(100 * with_glitch, 0) +
         " % of the slices hold a glitch); normalized_dtw keeps the slice's own line.";
}

// The claims that do not hold, and the ablations under which they do.
std::string UnheldClaimsSection(const std::vector<ClaimResult>& main, const HoldsWith& holds_with) {
  std::string s =
      "## Claims that do not hold (or are inconclusive), and the ablations under which they hold\n\n";
  bool any = false;
  for (const ClaimResult& c : main) {
    if (c.verdict == evaluation::Verdict::kHolds) continue;
    any = true;
    s += "- " + c.spec.id + " (" + c.spec.text + "): " + evaluation::VerdictName(c.verdict) + " here; ";
    const auto it = holds_with.find(c.spec.id);
    if (it == holds_with.end()) {
      s += "no ablation of this sweep makes it hold.";
    } else {
      s += "holds with ";
      for (std::size_t i = 0; i < it->second.size(); ++i) s += (i ? ", " : "") + it->second[i];
      s += ".";
    }
    if (c.available && std::abs(c.test.mean_diff) < 1e-3 && std::abs(c.test.ci_low) < 1e-3 &&
        std::abs(c.test.ci_high) < 1e-3)
      s += " A and B agree within 1 mm on every resample: the two methods leave the IMU (almost) unchanged "
           "alike, so they are (almost) the same run per seed and no difference can be shown.";
    const bool dtw_explains = it != holds_with.end() && !it->second.empty() &&
                              it->second.front().find("normalized_dtw") != std::string::npos;
    if (dtw_explains) s += RawDtwExplanation();
    s += "\n";
  }
  if (!any) s += "Every claim holds.\n";
  return s;
}

// The sweep's other estimators (configs/estimators_glitch_study.yaml): every prefix P whose methods P_trunc,
// P_dtw and P_original all exist, in name order.
std::vector<std::string> OtherEstimators(const SeedResults& r) {
  const std::string original = "_original";
  std::set<std::string> prefixes;
  for (const auto& [group, methods] : r.ate_m)
    for (const auto& [method, values] : methods)
      if (method.size() > original.size() &&
          method.compare(method.size() - original.size(), original.size(), original) == 0)
        prefixes.insert(method.substr(0, method.size() - original.size()));
  std::vector<std::string> out;
  for (const std::string& p : prefixes)
    if (std::all_of(std::begin(kPaperMethods), std::end(kPaperMethods),
                    [&](const char* m) { return HasMethod(r, p + "_" + m); }))
      out.push_back(p);
  return out;
}

// One table: each claim's verdict for vigil's estimator and for every other estimator.
std::string VerdictsTable(const std::vector<ClaimResult>& main,
                          const std::map<std::string, std::vector<ClaimResult>>& others) {
  std::string s = "| claim | statement (A < B) | vigil's estimator |";
  for (const auto& [prefix, claims] : others) s += " " + prefix + " |";
  s += "\n|---|---|---|";
  for (std::size_t i = 0; i < others.size(); ++i) s += "---|";
  s += "\n";
  for (std::size_t c = 0; c < main.size(); ++c) {
    s += "| " + main[c].spec.id + " | " + main[c].spec.text + " | " +
         evaluation::VerdictName(main[c].verdict) + " |";
    for (const auto& [prefix, claims] : others)
      s += std::string(" ") + evaluation::VerdictName(claims[c].verdict) + " |";
    s += "\n";
  }
  return s + "\n";
}

// Every claim and vigil's variants again for each other estimator of the sweep, judged as for vigil's own
// (empty when the sweep has none).
std::string EstimatorsSection(const SeedResults& results, const std::vector<ClaimResult>& main,
                              const evaluation::PairedTestOptions& options) {
  const std::vector<std::string> prefixes = OtherEstimators(results);
  if (prefixes.empty()) return "";
  std::map<std::string, std::vector<ClaimResult>> others;
  std::string details;
  for (const std::string& p : prefixes) {
    const SeedResults r = EstimatorResults(results, p);
    HoldsWith unused;
    details += ClaimsSection("Estimator `" + p + "`: claims", r, options, &others[p]);
    details +=
        VariantsSection("Estimator `" + p + "`: vigil's variants of the same methods", r, options, &unused);
  }
  std::string s = "\n## The claims per estimator\n\n";
  s += "The sweep runs other estimators behind the same recordings, glitches and detectors: the methods "
       "`<estimator>_<method>` (e.g. `" +
       prefixes.front() +
       "_trunc`). Each estimator's claims are judged as vigil's above, on its own runs, with its methods in "
       "place of trunc, dtw and original (and of vigil's variants).\n\n";
  return s + VerdictsTable(main, others) + details;
}

}  // namespace

SeedResults EstimatorResults(const SeedResults& results, const std::string& prefix) {
  const std::string head = prefix + "_";
  const auto own = [&](const std::string& method) {
    return method.size() > head.size() && method.compare(0, head.size(), head) == 0;
  };
  SeedResults out;
  for (const auto& [group, methods] : results.ate_m)
    for (const auto& [method, values] : methods)
      if (own(method)) out.ate_m[group][method.substr(head.size())] = values;
  for (const auto& [group, methods] : results.failed)
    for (const auto& [method, n] : methods)
      if (own(method)) out.failed[group][method.substr(head.size())] = n;
  for (const auto& [method, values] : results.re_trans_m)
    if (own(method)) out.re_trans_m[method.substr(head.size())] = values;
  for (const auto& [method, values] : results.re_yaw_deg)
    if (own(method)) out.re_yaw_deg[method.substr(head.size())] = values;
  return out;
}

std::string ReproductionMarkdown(const std::string& sweep, std::size_t seeds, const SeedResults& results,
                                 const std::map<std::string, SeedResults>& noise_models) {
  const evaluation::PairedTestOptions options;
  std::vector<ClaimResult> main;
  HoldsWith holds_with;
  std::string s = IntroductionSection(sweep, seeds, options);
  s += ClaimsSection("Claims", results, options, &main);
  s += VariantsSection("Ablation: vigil's variants of the same methods", results, options, &holds_with);
  s += NoiseModelSection(results, noise_models, options, &holds_with);
  s += UnheldClaimsSection(main, holds_with);
  return s + EstimatorsSection(results, main, options);
}

bool WriteReproduction(const fs::path& dir, const experiments::SweepSpec& spec) {
  const SeedResults results = ReadSeedResults(dir, spec);
  if (!HasPaperGrid(results)) return false;
  std::map<std::string, SeedResults> noise_models;
  std::error_code ec;
  const fs::path ablation = dir / kNoiseAblationDir;
  if (fs::is_regular_file(ablation / "sweep.yaml", ec)) {
    const experiments::SweepSpec ablation_spec =
        experiments::LoadSweepSpec((ablation / "sweep.yaml").string());
    noise_models = SplitByLastGroupLabel(ReadSeedResults(ablation, ablation_spec));
  }
  WriteFileAtomic(dir / "reproduction.md",
                  ReproductionMarkdown(spec.path, spec.seeds.size(), results, noise_models));
  return true;
}

}  // namespace vigil::report
