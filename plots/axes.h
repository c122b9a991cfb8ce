// 2-D axes: data series (lines, scatter, box plots, shaded spans) mapped into a plot area with
// ticks at nice numbers, numeric tick labels, a title, axis labels with units and a legend.
//
// Ranges come from the data (padded) unless set; equal_aspect makes one metre the same number of pixels on
// both axes (trajectory views) by widening the range of one axis. After Draw(), layout() tells where the
// plot area ended up and which data range it shows, so callers and tests can map data to pixels.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "plots/legend.h"
#include "plots/panel.h"

namespace vigil::plots {

// Five-number summary drawn by a box plot.
struct BoxStats {
  double whisker_lo = 0.0, q1 = 0.0, median = 0.0, q3 = 0.0, whisker_hi = 0.0;
};

// Quartiles (linear interpolation) and Tukey whiskers (the most extreme values within 1.5 IQR of the box).
// `values` must not be empty.
BoxStats BoxStatsOf(std::vector<double> values);

struct AxesLayout {
  Rect plot;  // the plot area in pixels
  double x_lo = 0.0, x_hi = 1.0, y_lo = 0.0, y_hi = 1.0;

  Eigen::Vector2d ToPixel(double x, double y) const {
    return {plot.x + (x - x_lo) / (x_hi - x_lo) * plot.w,
            plot.bottom() - (y - y_lo) / (y_hi - y_lo) * plot.h};
  }
};

class Axes : public Panel {
 public:
  std::string title, x_label, y_label;
  bool equal_aspect = false;
  bool grid = true;
  LegendPosition legend = LegendPosition::kUpperRight;

  void SetXLimits(double lo, double hi) { x_limits_ = {lo, hi}; }
  void SetYLimits(double lo, double hi) { y_limits_ = {lo, hi}; }
  // Replaces the numeric x ticks by labelled positions (categorical axes, e.g. glitch settings).
  void SetXCategories(std::vector<std::pair<double, std::string>> ticks) { x_categories_ = std::move(ticks); }

  void Line(std::vector<double> x, std::vector<double> y, const Color& color, const std::string& label = "",
            double width_scale = 1.0, bool dashed = false);
  void Scatter(std::vector<double> x, std::vector<double> y, const Color& color,
               const std::string& label = "", double radius_scale = 1.0);
  // A box plot at x with half width `half_width` (data units).
  void Box(double x, const BoxStats& stats, double half_width, const Color& color,
           const std::string& label = "");
  // A vertical band x0 <= x <= x1 over the whole height.
  void Span(double x0, double x1, const Color& color, const std::string& label = "");

  void Draw(Painter& painter, const Rect& cell, const Style& style) override;
  const AxesLayout& layout() const { return layout_; }

 private:
  struct LineData {
    std::vector<double> x, y;
    Color color;
    double width_scale;
    bool dashed;
  };
  struct ScatterData {
    std::vector<double> x, y;
    Color color;
    double radius_scale;
  };
  struct BoxData {
    double x;
    BoxStats stats;
    double half_width;
    Color color;
  };
  struct SpanData {
    double x0, x1;
    Color color;
  };

  void DataRange(double* x_lo, double* x_hi, double* y_lo, double* y_hi) const;
  void DrawData(Painter& painter, const Style& style) const;

  std::vector<LineData> lines_;
  std::vector<ScatterData> scatters_;
  std::vector<BoxData> boxes_;
  std::vector<SpanData> spans_;
  std::vector<LegendEntry> legend_entries_;
  std::optional<std::pair<double, double>> x_limits_, y_limits_;
  std::vector<std::pair<double, std::string>> x_categories_;
  AxesLayout layout_;
};

}  // namespace vigil::plots
