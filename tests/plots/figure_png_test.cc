#include "plots/figure_png.h"

#include <gtest/gtest.h>

#include "core/output.h"
#include "plots/image.h"
#include "tests/core/test_util.h"

namespace vigil::plots {
namespace {

Figure OneLine() {
  Figure figure(1, 1, "one line");
  Axes& axes = figure.AddAxes(0, 0);
  axes.Line({0.0, 1.0}, {0.0, 1.0}, Color{1.0f, 0.0f, 0.0f, 1.0f}, "line");
  return figure;
}

TEST(WriteFigurePng, WritesTheFigureAtTheOptionsSize) {
  vigil::testing::TempDir tmp;
  FigureOptions options;
  options.width = 640;
  options.height = 400;
  WriteFigurePng(OneLine(), tmp.path() / "f.png", options);
  const Image image = DecodePng(ReadFile(tmp.path() / "f.png"));
  EXPECT_EQ(image.width, 640);
  EXPECT_EQ(image.height, 400);
  // Drawn on: not a blank page.
  std::size_t dark = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) dark += image.Pixel(x, y)[0] < 128;
  EXPECT_GT(dark, 100u);
}

TEST(WriteFigurePng, RefusesABadSizeBeforeWritingAnything) {
  vigil::testing::TempDir tmp;
  FigureOptions options;
  options.width = 10;
  EXPECT_FALSE(vigil::testing::InputErrorOf([&] {
                 WriteFigurePng(OneLine(), tmp.path() / "f.png", options);
               }).empty());
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "f.png"));
}

}  // namespace
}  // namespace vigil::plots
