// Figure builders on known data: values land where the axes say they should.
#include "plots/figures.h"

#include <gtest/gtest.h>

#include "tests/plots/image_checks.h"

namespace vigil::plots {
namespace {

class FiguresTest : public ::testing::Test {
 protected:
  gl::GlContext gl_;
  TextRenderer text_;
};

bool Near(const uint8_t* p, const Color& c, int tolerance) {
  return std::abs(p[0] - c.r * 255) <= tolerance && std::abs(p[1] - c.g * 255) <= tolerance &&
         std::abs(p[2] - c.b * 255) <= tolerance;
}

TEST_F(FiguresTest, SummaryBoxSitsAtItsMedian) {
  SummaryCell cell;
  cell.method = "dtw";
  cell.setting = 1;
  cell.ate_trans_m = {1.0, 2.0, 3.0, 4.0, 5.0};
  cell.ate_rot_deg = {10.0, 20.0, 30.0, 40.0, 50.0};
  Figure figure = SummaryFigure({"a", "b"}, {"dtw"}, {cell});
  const Image image = figure.Render(&gl_, &text_, 1000, 600);
  const AxesLayout& L = figure.axes(0)->layout();
  // Inside the box (between the quartiles 2 and 4, at the setting's x) the method's colour shows through.
  const Eigen::Vector2d inside = L.ToPixel(1.0 - 0.1, 3.5);
  const uint8_t* p = testing::At(image, inside.x(), inside.y());
  EXPECT_GT(p[1], p[0]) << "dtw is green";
  // The median line (black) at y = 3, and nothing above the top whisker (5).
  const Eigen::Vector2d median = L.ToPixel(1.0 - 0.1, 3.0);
  EXPECT_LT(testing::At(image, median.x(), median.y())[0], 80);
  const Eigen::Vector2d above = L.ToPixel(1.0 - 0.1, 5.3);
  EXPECT_TRUE(testing::IsWhite(image, above.x(), above.y()) ||
              Near(testing::At(image, above.x(), above.y()), kGridColor, 3));
  // The y axis starts at zero and covers the largest seed.
  EXPECT_EQ(L.y_lo, 0.0);
  EXPECT_GE(L.y_hi, 5.0);
}

TEST_F(FiguresTest, DetectionShadesFlaggedSamples) {
  DetectionTrace trace;
  trace.detector = "trunc";
  trace.axis_name = "a_z";
  trace.unit = "m/s²";
  for (int i = 0; i < 400; ++i) {
    trace.t_s.push_back(i * 0.005);
    const bool glitch = i >= 200 && i < 204;
    trace.raw.push_back(glitch ? 20.0 : 9.81);
    trace.mitigated.push_back(9.81);
    trace.flagged.push_back(glitch);
  }
  trace.excerpt_t0_s = 0.9;
  trace.excerpt_t1_s = 1.1;
  Figure figure = DetectionFigure(trace);
  const Image image = figure.Render(&gl_, &text_, 1000, 800);
  const AxesLayout& L = figure.axes(1)->layout();  // the excerpt
  EXPECT_DOUBLE_EQ(L.x_lo, 0.9);
  // In the flagged span, away from the lines: the shading colour (orange, translucent) over white.
  const Eigen::Vector2d shaded = L.ToPixel(1.0075, 15.0);
  const uint8_t* p = testing::At(image, shaded.x(), shaded.y());
  EXPECT_FALSE(testing::IsWhite(image, shaded.x(), shaded.y()));
  EXPECT_GT(p[0], p[2]);
  const Eigen::Vector2d clear = L.ToPixel(0.95, 15.0);
  EXPECT_TRUE(testing::IsWhite(image, clear.x(), clear.y()));
  // The mitigated line at 9.81 is drawn across the excerpt.
  const Eigen::Vector2d line = L.ToPixel(0.95, 9.81);
  const uint8_t* q = testing::At(image, line.x(), line.y());
  EXPECT_GT(q[2], q[0] + 60) << int(q[0]) << " " << int(q[1]) << " " << int(q[2]);
}

TEST_F(FiguresTest, TrajectoryTopViewKeepsMetresSquare) {
  TrajectoryPanel panel;
  panel.label = "test";
  for (int i = 0; i <= 100; ++i) {
    const double a = i * 2 * M_PI / 100;
    panel.groundtruth_W.emplace_back(10 * std::cos(a), 2 * std::sin(a), 0);
  }
  panel.estimates.push_back({"dtw", panel.groundtruth_W});
  Figure figure = TrajectoryFigure({panel});
  const Image image = figure.Render(&gl_, &text_, 1200, 600);
  const AxesLayout& L = figure.axes(0)->layout();
  const double px_per_m_x = L.plot.w / (L.x_hi - L.x_lo), px_per_m_y = L.plot.h / (L.y_hi - L.y_lo);
  EXPECT_NEAR(px_per_m_x, px_per_m_y, 1e-6 * px_per_m_x);
  // The estimate (green, drawn over the ground truth) passes through (10, 0).
  const Eigen::Vector2d p = L.ToPixel(10.0, 0.0);
  EXPECT_GT(testing::At(image, p.x(), p.y())[1], testing::At(image, p.x(), p.y())[0]);
}

}  // namespace
}  // namespace vigil::plots
