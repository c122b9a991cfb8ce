#include "report/claims.h"

#include <gtest/gtest.h>

#include "core/random.h"
#include "evaluation/paired_test.h"
#include "report/reproduction.h"

namespace vigil::report {
namespace {

// Ten seeds of base + offset + seed-to-seed noise of the given std (shared noise when `shared` is true: a
// paired design sees through it).
evaluation::SeedValues Series(double mean, double noise_std, uint64_t stream) {
  Rng rng(stream, "series");
  evaluation::SeedValues v;
  for (uint64_t seed = 1; seed <= 10; ++seed) v[seed] = mean + noise_std * rng.Normal();
  return v;
}

evaluation::SeedValues Shifted(const evaluation::SeedValues& base, double shift, double noise_std,
                               uint64_t stream) {
  Rng rng(stream, "shift");
  evaluation::SeedValues v;
  for (const auto& [seed, x] : base) v[seed] = x + shift + noise_std * rng.Normal();
  return v;
}

// The paper's grid with trunc / dtw / original ATE per group, from a function of (group, method).
template <class F>
SeedResults Grid(F ate) {
  SeedResults r;
  for (const char* g : {"noise_0_1", "noise_1_10", "noise_50_10"})
    for (const char* m : {"trunc", "dtw", "original"}) r.ate_m[g][m] = ate(std::string(g), std::string(m));
  return r;
}

const ClaimSpec& Claim(const std::string& id) {
  static const std::vector<ClaimSpec> claims = PaperClaims();
  for (const ClaimSpec& c : claims)
    if (c.id == id) return c;
  throw std::logic_error("no claim " + id);
}

TEST(Claims, PaperLikeResultsMakeEveryTable2ClaimHold) {
  // The paper's table 2 as the true means, a shared per-seed level and small independent noise.
  const std::map<std::string, std::map<std::string, double>> paper = {
      {"noise_0_1", {{"trunc", 0.04}, {"dtw", 0.06}, {"original", 0.06}}},
      {"noise_1_10", {{"trunc", 0.14}, {"dtw", 0.15}, {"original", 0.15}}},
      {"noise_50_10", {{"trunc", 0.32}, {"dtw", 0.06}, {"original", 18.05}}}};
  uint64_t stream = 10;
  SeedResults r = Grid([&](const std::string& g, const std::string& m) {
    return Shifted(Series(0.0, 0.0, 1), paper.at(g).at(m), 0.001, ++stream);
  });
  r.re_trans_m["dtw"] = Series(0.1, 0.01, 30);
  r.re_trans_m["trunc"] = Shifted(r.re_trans_m["dtw"], 0.2, 0.01, 31);
  r.re_yaw_deg["dtw"] = Series(0.1, 0.01, 32);
  r.re_yaw_deg["trunc"] = Shifted(r.re_yaw_deg["dtw"], 0.4, 0.01, 33);
  for (const ClaimSpec& c : PaperClaims()) {
    const ClaimResult res = EvaluateClaim(c, r);
    EXPECT_TRUE(res.available) << c.id;
    EXPECT_EQ(res.verdict, evaluation::Verdict::kHolds)
        << c.id << " " << res.test.ci_low << " " << res.test.ci_high;
  }
}

TEST(Claims, ALossAndATieAreJudgedAsSuch) {
  // trunc clearly below dtw at N(50,10) (d1 does not hold); trunc and dtw equal at N(0,1) (c1 inconclusive).
  uint64_t stream = 100;
  const evaluation::SeedValues level = Series(0.05, 0.01, 2);
  const SeedResults r = Grid([&](const std::string& g, const std::string& m) {
    if (g == "noise_50_10" && m == "dtw") return Shifted(level, 0.03, 0.002, ++stream);
    if (g == "noise_0_1" && m == "dtw") {  // differences +-0.01 in turn: mean exactly 0
      evaluation::SeedValues v = level;
      for (auto& [seed, x] : v) x += seed % 2 ? 0.01 : -0.01;
      return v;
    }
    if (g == "noise_0_1" && m == "trunc") return level;
    return Shifted(level, 0.0, 0.002, ++stream);
  });
  EXPECT_EQ(EvaluateClaim(Claim("d1"), r).verdict, evaluation::Verdict::kDoesNotHold);
  EXPECT_EQ(EvaluateClaim(Claim("c1"), r).verdict, evaluation::Verdict::kInconclusive);
  // Relative-error claims without relative errors are unavailable, hence inconclusive.
  const ClaimResult d2 = EvaluateClaim(Claim("d2"), r);
  EXPECT_FALSE(d2.available);
  EXPECT_EQ(d2.verdict, evaluation::Verdict::kInconclusive);
}

TEST(Claims, RenamingSwapsInVigilsVariants) {
  bool changed = false;
  const ClaimSpec v = RenameMethods(Claim("d1"), {{"dtw", "normalized_dtw"}}, &changed);
  EXPECT_TRUE(changed);
  EXPECT_EQ(v.method_a, "normalized_dtw");
  EXPECT_EQ(v.method_b, "trunc");
  RenameMethods(Claim("a2"), {{"dtw", "normalized_dtw"}}, &changed);
  EXPECT_FALSE(changed);
}

TEST(Reproduction, SplitsTheNoiseAblationByModelAndKnowsThePaperGrid) {
  SeedResults r;
  r.ate_m["noise_0_1-vins_euroc"]["original"] = {{1, 3.0}};
  r.ate_m["noise_0_1-matched"]["original"] = {{1, 0.1}};
  r.failed["noise_0_1-vins_euroc"]["original"] = 2;
  const auto split = SplitByLastGroupLabel(r);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split.at("vins_euroc").Ate("noise_0_1", "original")->at(1), 3.0);
  EXPECT_EQ(split.at("vins_euroc").Failed("noise_0_1", "original"), 2u);
  EXPECT_FALSE(HasPaperGrid(r));
  EXPECT_TRUE(
      HasPaperGrid(Grid([](const std::string&, const std::string&) { return evaluation::SeedValues{}; })));
  const std::string md = ReproductionMarkdown(
      "x.yaml", 10, Grid([](const std::string&, const std::string&) { return Series(0.1, 0.01, 1); }), {});
  EXPECT_NE(md.find("| a1 |"), std::string::npos);
  EXPECT_NE(md.find("| d3 |"), std::string::npos);
}

// The noise ablation's collapse table and the explanation of a claim that normalized_dtw makes hold: their
// paper numbers (paper_reference.h) and the DTW slice arithmetic, as written in reproduction.md.
TEST(Reproduction, CollapseTableAndDtwExplanationQuoteThePaper) {
  uint64_t stream = 200;
  const evaluation::SeedValues level = Series(0.1, 0.01, 3);
  SeedResults r = Grid([&](const std::string& g, const std::string& m) {
    return Shifted(level, g == "noise_50_10" && m == "dtw" ? 0.5 : 0.0, 0.002, ++stream);
  });
  for (const char* g : {"noise_0_1", "noise_1_10", "noise_50_10"})
    r.ate_m[g]["normalized_dtw"] = Shifted(level, -0.05, 0.002, ++stream);
  const SeedResults model = Grid([&](const std::string& g, const std::string& m) {
    return Shifted(level, g == "noise_50_10" && m == "original" ? 9.0 : 0.0, 0.002, ++stream);
  });
  const std::string md = ReproductionMarkdown("x.yaml", 10, r, {{"vins_euroc", model}});
  EXPECT_NE(
      md.find("\nThe paper's collapse: original at N(50,10) reaches 18.05 m, while every other cell of its "
              "table 2 is at most 0.32 m.\n"),
      std::string::npos);
  EXPECT_NE(
      md.find("collapse of the paper's order of magnitude (>= 6 m) | largest other cell of table 2 [m] | "
              "other cells as the paper's (<= 0.32 m) |\n"),
      std::string::npos);
  // vins_euroc collapses like the paper (original about 9.1 m, every other cell about 0.1 m); matched does
  // not.
  const auto row = [&](const std::string& name) {
    const std::size_t at = md.find("| " + name + " | ", md.find("| noise model |"));
    return at == std::string::npos ? std::string() : md.substr(at, md.find('\n', at) - at);
  };
  const std::string vins = row("vins_euroc");
  ASSERT_GT(vins.size(), 8u);
  EXPECT_NE(vins.find("| 0 | yes | "), std::string::npos) << vins;
  EXPECT_EQ(vins.substr(vins.size() - 8), " | yes |") << vins;
  EXPECT_NE(row("matched").find("| 0 | no | "), std::string::npos) << row("matched");
  EXPECT_NE(md.find("- d1 (dtw beats trunc at N(50,10) (table 2)): does not hold here; holds with dtw -> "
                    "normalized_dtw. The difference from the paper that explains it:"),
            std::string::npos);
  EXPECT_NE(md.find("(at glitch rate 0.01 and M = 40, 1 - 0.99^40 = 33 % of the slices hold a glitch); "
                    "normalized_dtw keeps the slice's own line.\n"),
            std::string::npos);
  EXPECT_NE(md.find("| d1 | dtw beats trunc at N(50,10) (table 2) | 0.06 < 0.32 m |"), std::string::npos);
  EXPECT_NE(md.find("| d3 | dtw has a lower relative yaw error than trunc over all settings (table 4) | "
                    "0.08-0.10 < 0.49-0.61 deg |"),
            std::string::npos);
}

// A sweep with a second estimator behind the same detectors (methods ext_trunc, ext_dtw, ext_original): its
// claims are judged on its own runs, and one table gives each claim's verdict per estimator.
TEST(Reproduction, AnotherEstimatorsClaimsAreJudgedOnItsOwnRuns) {
  uint64_t stream = 300;
  const evaluation::SeedValues level = Series(0.1, 0.01, 4);
  // vigil: dtw clearly below trunc at N(50,10) (d1 holds); ext: dtw clearly above (d1 does not hold).
  SeedResults r = Grid([&](const std::string& g, const std::string& m) {
    return Shifted(level, g == "noise_50_10" && m == "trunc" ? 0.3 : 0.0, 0.002, ++stream);
  });
  for (const char* g : {"noise_0_1", "noise_1_10", "noise_50_10"})
    for (const char* m : {"trunc", "dtw", "original"})
      r.ate_m[g][std::string("ext_") + m] = Shifted(
          level, std::string(g) == "noise_50_10" && std::string(m) == "dtw" ? 0.3 : 0.0, 0.002, ++stream);
  r.failed["noise_0_1"]["ext_original"] = 1;
  r.ate_m["noise_0_1"]["ext_hampel"] = level;     // an estimator's method beside the paper's three
  r.ate_m["noise_0_1"]["only_original"] = level;  // a prefix without trunc and dtw is no estimator

  const SeedResults ext = EstimatorResults(r, "ext");
  EXPECT_EQ(ext.ate_m.at("noise_50_10").size(), 3u);
  EXPECT_EQ(ext.ate_m.at("noise_0_1").count("hampel"), 1u);
  EXPECT_EQ(ext.Failed("noise_0_1", "original"), 1u);
  EXPECT_EQ(EvaluateClaim(Claim("d1"), r).verdict, evaluation::Verdict::kHolds);
  EXPECT_EQ(EvaluateClaim(Claim("d1"), ext).verdict, evaluation::Verdict::kDoesNotHold);

  const std::string md = ReproductionMarkdown("x.yaml", 10, r, {});
  EXPECT_NE(md.find("| d1 | dtw beats trunc at N(50,10) (table 2) | holds | does not hold |\n"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("## Estimator `ext`: claims\n"), std::string::npos);
  EXPECT_EQ(md.find("Estimator `only`"), std::string::npos);
  EXPECT_EQ(ReproductionMarkdown("x.yaml", 10,
                                 Grid([&](const std::string&, const std::string&) { return level; }), {})
                .find("The claims per estimator"),
            std::string::npos);
}

}  // namespace
}  // namespace vigil::report
