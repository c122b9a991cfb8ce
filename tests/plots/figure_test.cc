// The plotting layer end to end: OSMesa shapes, FreeType text, layout, PNG.
#include "plots/figure.h"

#include <cstdlib>

#include <gtest/gtest.h>

#include "plots/style.h"
#include "tests/plots/image_checks.h"

namespace vigil::plots {
namespace {

class FigureTest : public ::testing::Test {
 protected:
  gl::GlContext gl_;
  TextRenderer text_;
};

TEST_F(FigureTest, DiagonalLineCrossesThePlotDiagonal) {
  Figure figure(1, 1, "diagonal");
  Axes& axes = figure.AddAxes(0, 0);
  axes.x_label = "x [m]";
  axes.y_label = "y [m]";
  axes.SetXLimits(0.0, 1.0);
  axes.SetYLimits(0.0, 1.0);
  axes.grid = false;
  const Color red{1.0f, 0.0f, 0.0f, 1.0f};
  axes.Line({0.0, 1.0}, {0.0, 1.0}, red, "line");
  const Image image = figure.Render(&gl_, &text_, 800, 500);
  ASSERT_EQ(image.width, 800);
  ASSERT_EQ(image.height, 500);
  if (const char* dir = std::getenv("VIGIL_PLOTS_TEST_OUTPUT"))
    WritePng(std::string(dir) + "/diagonal.png", image);
  const AxesLayout& L = axes.layout();
  EXPECT_GT(L.plot.w, 600);
  EXPECT_GT(L.plot.h, 300);
  // Every point of the data diagonal (away from the legend) is red; points off it are white.
  for (double t : {0.1, 0.3, 0.5, 0.7}) {
    const Eigen::Vector2d p = L.ToPixel(t, t);
    EXPECT_TRUE(testing::IsReddish(image, p.x(), p.y())) << "t = " << t;
    const Eigen::Vector2d q = L.ToPixel(t, t + 0.2);
    EXPECT_TRUE(testing::IsWhite(image, q.x(), q.y())) << "t = " << t;
  }
  // Anti-aliased: some pixels next to the line are between red and white.
  EXPECT_GT(testing::CountPartialRed(image, L.plot), 50);
  // Text was drawn: dark pixels below the plot area (tick labels) and left of it (y label).
  EXPECT_GT(testing::CountDark(image, {L.plot.x, L.plot.bottom() + 10, L.plot.w, 500 - L.plot.bottom() - 10}),
            50);
  EXPECT_GT(testing::CountDark(image, {0, L.plot.y, L.plot.x - 10, L.plot.h}), 50);
}

TEST_F(FigureTest, RenderingIsDeterministicAndSizeConfigurable) {
  auto make = [] {
    auto figure = std::make_unique<Figure>(1, 2, "two panels");
    Axes& a = figure->AddAxes(0, 0);
    a.Scatter({1, 2, 3}, {3, 1, 2}, PaletteColor(0), "points");
    a.Box(4.0, BoxStatsOf({1.0, 2.0, 2.5, 3.0, 9.0}), 0.3, PaletteColor(1), "box");
    a.Span(1.5, 1.7, PaletteColor(2).WithAlpha(0.3f));
    Axes3D& b = figure->AddAxes3D(0, 1);
    b.Line({{0, 0, 0}, {1, 1, 1}, {2, 0, 1}}, PaletteColor(3), "path");
    b.Points({{0, 1, 0}, {1, 0, 2}}, PaletteColor(4), "points");
    return figure;
  };
  const Image first = make()->Render(&gl_, &text_, 640, 400);
  const Image second = make()->Render(&gl_, &text_, 640, 400);
  EXPECT_EQ(testing::CountDifferentPixels(first, second), 0);
  EXPECT_TRUE(EncodePng(first) == EncodePng(second));
  const Image small = make()->Render(&gl_, &text_, 321, 203);
  EXPECT_EQ(small.width, 321);
  EXPECT_EQ(small.height, 203);
}

TEST_F(FigureTest, PerspectiveViewPutsPointsWhereTheMatricesSay) {
  Figure figure(1, 1);
  Axes3D& view = figure.AddAxes3D(0, 0);
  const Color blue{0.0f, 0.0f, 1.0f, 1.0f};
  view.Points({{0, 0, 0}, {4, 2, 1}}, blue, "", 4.0);
  view.Line({{0, 0, 0}, {4, 2, 1}}, blue);
  const Image image = figure.Render(&gl_, &text_, 600, 600);
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 2, 1), Eigen::Vector3d(2, 1, 0.5)}) {
    const Eigen::Vector2d px = view.ToPixel(p);
    EXPECT_TRUE(testing::IsBluish(image, px.x(), px.y())) << p.transpose();
  }
}

TEST(BoxStats, QuartilesAndWhiskers) {
  const BoxStats s = BoxStatsOf({1, 2, 3, 4, 5, 6, 7, 8, 9, 100});
  EXPECT_DOUBLE_EQ(s.median, 5.5);
  EXPECT_DOUBLE_EQ(s.q1, 3.25);
  EXPECT_DOUBLE_EQ(s.q3, 7.75);
  EXPECT_DOUBLE_EQ(s.whisker_lo, 1.0);
  EXPECT_DOUBLE_EQ(s.whisker_hi, 9.0);  // 100 is an outlier
}

}  // namespace
}  // namespace vigil::plots
