#include "plots/method_colors.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "plots/style.h"

namespace vigil::plots {
namespace {

std::tuple<float, float, float> Rgb(const Color& c) { return {c.r, c.g, c.b}; }

bool Same(const Color& a, const Color& b) { return Rgb(a) == Rgb(b); }

TEST(MethodColors, ThePapersMethodsKeepTheirColourInEveryFigure) {
  const MethodColors few({"trunc", "original"});
  const MethodColors many({"none", "relative_threshold", "hampel", "original", "dtw", "trunc"});
  for (const MethodColors* colors : {&few, &many}) {
    EXPECT_TRUE(Same(colors->Of("original"), PaletteColor(1)));
    EXPECT_TRUE(Same(colors->Of("trunc"), PaletteColor(0)));
  }
  EXPECT_TRUE(Same(many.Of("dtw"), PaletteColor(2)));
  EXPECT_TRUE(Same(many.Of("hampel"), PaletteColor(3)));
}

TEST(MethodColors, NoTwoMethodsOfAFigureShareAColourWhileThePaletteLasts) {
  // Under a hash of the name onto four colours, normalized_dtw and threshold shared one, as did
  // relative_threshold and none.
  const std::vector<std::string> methods = {
      "original", "trunc", "dtw", "hampel", "none", "threshold", "normalized_dtw", "relative_threshold"};
  const MethodColors colors(methods);
  std::set<std::tuple<float, float, float>> seen;
  for (const std::string& m : methods) EXPECT_TRUE(seen.insert(Rgb(colors.Of(m))).second) << m;
}

TEST(MethodColors, AnEstimatorsVariantsShareTheirMethodsHueInAShadeOfTheirOwn) {
  // The glitch study across estimators: twelve methods, six hues, OpenVINS's in a darker shade.
  const std::vector<std::string> methods = {"trunc",
                                            "openvins_trunc",
                                            "dtw",
                                            "openvins_dtw",
                                            "original",
                                            "openvins_original",
                                            "relative_threshold",
                                            "openvins_relative_threshold",
                                            "normalized_dtw",
                                            "openvins_normalized_dtw",
                                            "hampel",
                                            "openvins_hampel"};
  const MethodColors colors(methods);
  std::set<std::tuple<float, float, float>> seen;
  for (const std::string& m : methods) EXPECT_TRUE(seen.insert(Rgb(colors.Of(m))).second) << m;
  const Color trunc = colors.Of("trunc"), openvins = colors.Of("openvins_trunc");
  EXPECT_TRUE(Same(trunc, PaletteColor(0)));
  EXPECT_LT(openvins.r + openvins.g + openvins.b, trunc.r + trunc.g + trunc.b);
  // relative_threshold is not a variant of a method "threshold" that the figure does not show, and a single
  // PREFIX_ (one method) is a method of its own, not a variant.
  const MethodColors lone({"trunc", "mine_trunc"});
  EXPECT_FALSE(Same(lone.Of("mine_trunc"), lone.Of("trunc")));
  EXPECT_TRUE(Same(lone.Of("mine_trunc"), PaletteColor(1)));
}

TEST(MethodColors, AMethodNotGivenIsGrey) {
  EXPECT_TRUE(Same(MethodColors({"trunc"}).Of("other"), PaletteColor(6)));
}

}  // namespace
}  // namespace vigil::plots
