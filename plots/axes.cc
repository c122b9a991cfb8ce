#include "plots/axes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "plots/ticks.h"

namespace vigil::plots {
namespace {

double Quantile(const std::vector<double>& sorted, double q) {
  const double pos = q * (sorted.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(pos));
  const double frac = pos - i;
  return i + 1 < sorted.size() ? sorted[i] * (1.0 - frac) + sorted[i + 1] * frac : sorted[i];
}

void Extend(double v, double* lo, double* hi) {
  if (!std::isfinite(v)) return;
  *lo = std::min(*lo, v);
  *hi = std::max(*hi, v);
}

// Ticks whose target count follows the axis length in pixels (about one per 90 px at scale 1).
Ticks AxisTicks(double lo, double hi, double length_px, const Style& style) {
  const int target = std::clamp(static_cast<int>(length_px / (90.0 * style.scale)), 2, 10);
  return NiceTicks(lo, hi, target);
}

}  // namespace

BoxStats BoxStatsOf(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  BoxStats s;
  s.q1 = Quantile(values, 0.25);
  s.median = Quantile(values, 0.5);
  s.q3 = Quantile(values, 0.75);
  const double iqr = s.q3 - s.q1;
  s.whisker_lo = s.q1;
  s.whisker_hi = s.q3;
  for (double v : values) {
    if (v >= s.q1 - 1.5 * iqr) s.whisker_lo = std::min(s.whisker_lo, v);
    if (v <= s.q3 + 1.5 * iqr) s.whisker_hi = std::max(s.whisker_hi, v);
  }
  return s;
}

void Axes::Line(std::vector<double> x, std::vector<double> y, const Color& color, const std::string& label,
                double width_scale, bool dashed) {
  lines_.push_back({std::move(x), std::move(y), color, width_scale, dashed});
  legend_entries_.push_back({label, color, LegendKind::kLine, dashed});
}

void Axes::Scatter(std::vector<double> x, std::vector<double> y, const Color& color, const std::string& label,
                   double radius_scale) {
  scatters_.push_back({std::move(x), std::move(y), color, radius_scale});
  legend_entries_.push_back({label, color, LegendKind::kMarker, false});
}

void Axes::Box(double x, const BoxStats& stats, double half_width, const Color& color,
               const std::string& label) {
  boxes_.push_back({x, stats, half_width, color});
  legend_entries_.push_back({label, color, LegendKind::kPatch, false});
}

void Axes::Span(double x0, double x1, const Color& color, const std::string& label) {
  spans_.push_back({std::min(x0, x1), std::max(x0, x1), color});
  legend_entries_.push_back({label, color, LegendKind::kPatch, false});
}

void Axes::DataRange(double* x_lo, double* x_hi, double* y_lo, double* y_hi) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  *x_lo = *y_lo = kInf;
  *x_hi = *y_hi = -kInf;
  for (const auto& l : lines_) {
    for (double v : l.x) Extend(v, x_lo, x_hi);
    for (double v : l.y) Extend(v, y_lo, y_hi);
  }
  for (const auto& s : scatters_) {
    for (double v : s.x) Extend(v, x_lo, x_hi);
    for (double v : s.y) Extend(v, y_lo, y_hi);
  }
  for (const auto& b : boxes_) {
    Extend(b.x - b.half_width, x_lo, x_hi);
    Extend(b.x + b.half_width, x_lo, x_hi);
    Extend(b.stats.whisker_lo, y_lo, y_hi);
    Extend(b.stats.whisker_hi, y_lo, y_hi);
  }
  for (const auto& s : spans_) {
    Extend(s.x0, x_lo, x_hi);
    Extend(s.x1, x_lo, x_hi);
  }
  for (const auto& c : x_categories_) Extend(c.first, x_lo, x_hi);
  constexpr double kPad = 0.04;
  if (x_limits_) {
    *x_lo = x_limits_->first;
    *x_hi = x_limits_->second;
  } else {
    // Categorical axes get half a category of room on both sides.
    PadRange(x_lo, x_hi, x_categories_.empty() ? kPad : 0.0);
    if (!x_categories_.empty()) {
      *x_lo -= 0.5;
      *x_hi += 0.5;
    }
  }
  if (y_limits_) {
    *y_lo = y_limits_->first;
    *y_hi = y_limits_->second;
  } else {
    PadRange(y_lo, y_hi, kPad);
  }
}

void Axes::Draw(Painter& painter, const Rect& cell, const Style& style) {
  double x_lo, x_hi, y_lo, y_hi;
  DataRange(&x_lo, &x_hi, &y_lo, &y_hi);
  const double pad = style.pad_px();
  // Vertical layout first: it does not depend on the width of the y tick labels.
  const double top = cell.y + pad + (title.empty() ? 0.0 : style.axes_title_px() * 1.5);
  const double bottom = cell.bottom() - pad - style.tick_px() * 1.6 - style.tick_len_px() -
                        (x_label.empty() ? 0.0 : style.label_px() * 1.6);
  Rect plot{0.0, top, 0.0, std::max(bottom - top, 10.0)};
  Ticks y_ticks = AxisTicks(y_lo, y_hi, plot.h, style);
  double label_w = 0.0;
  for (double v : y_ticks.values) {
    label_w = std::max(label_w, static_cast<double>(
                                    painter.MeasureText(FormatTick(v, y_ticks.step), style.tick_px()).width));
  }
  const double legend_w = legend == LegendPosition::kOutsideRight
                              ? LegendWidth(painter, legend_entries_, style) + 2.0 * pad
                              : 0.0;
  plot.x =
      cell.x + pad + (y_label.empty() ? 0.0 : style.label_px() * 1.6) + label_w + style.tick_len_px() + pad;
  plot.w = std::max(cell.right() - 2.0 * pad - legend_w - plot.x, 10.0);

  if (equal_aspect) {
    // Widen the range whose metres-per-pixel is smaller.
    const double sx = (x_hi - x_lo) / plot.w, sy = (y_hi - y_lo) / plot.h;
    if (sx > sy) {
      const double c = (y_lo + y_hi) / 2, half = sx * plot.h / 2;
      y_lo = c - half;
      y_hi = c + half;
    } else {
      const double c = (x_lo + x_hi) / 2, half = sy * plot.w / 2;
      x_lo = c - half;
      x_hi = c + half;
    }
    y_ticks = AxisTicks(y_lo, y_hi, plot.h, style);
  }
  layout_ = {plot, x_lo, x_hi, y_lo, y_hi};
  const Ticks x_ticks = AxisTicks(x_lo, x_hi, plot.w, style);

  // Grid.
  if (grid) {
    painter.SetClip(plot);
    const double gw = std::max(1.0, style.scale);
    for (double v : y_ticks.values) {
      const double py = layout_.ToPixel(x_lo, v).y();
      painter.FillRect({plot.x, py - gw / 2, plot.w, gw}, kGridColor);
    }
    if (x_categories_.empty()) {
      for (double v : x_ticks.values) {
        const double px = layout_.ToPixel(v, y_lo).x();
        painter.FillRect({px - gw / 2, plot.y, gw, plot.h}, kGridColor);
      }
    }
    painter.ClearClip();
  }

  painter.SetClip(plot);
  DrawData(painter, style);
  painter.ClearClip();

  // Frame, ticks and tick labels.
  painter.StrokeRect(plot, kFrameColor, style.frame_px());
  const double tl = style.tick_len_px(), tw = style.frame_px();
  for (double v : y_ticks.values) {
    const double py = layout_.ToPixel(x_lo, v).y();
    painter.FillRect({plot.x - tl, py - tw / 2, tl, tw}, kFrameColor);
    painter.Text(FormatTick(v, y_ticks.step), style.tick_px(), plot.x - tl - pad / 2, py, HAlign::kRight,
                 VAlign::kMiddle, kTextColor);
  }
  std::vector<std::pair<double, std::string>> x_labels = x_categories_;
  if (x_labels.empty()) {
    for (double v : x_ticks.values) x_labels.emplace_back(v, FormatTick(v, x_ticks.step));
  }
  for (const auto& [v, text] : x_labels) {
    const double px = layout_.ToPixel(v, y_lo).x();
    if (px < plot.x - 0.5 || px > plot.right() + 0.5) continue;
    painter.FillRect({px - tw / 2, plot.bottom(), tw, tl}, kFrameColor);
    painter.Text(text, style.tick_px(), px, plot.bottom() + tl + pad / 2, HAlign::kCenter, VAlign::kTop,
                 kTextColor);
  }

  // Title and axis labels.
  if (!title.empty()) {
    painter.Text(title, style.axes_title_px(), plot.x + plot.w / 2, plot.y - pad, HAlign::kCenter,
                 VAlign::kBottom, kTextColor);
  }
  if (!x_label.empty()) {
    painter.Text(x_label, style.label_px(), plot.x + plot.w / 2, cell.bottom() - pad, HAlign::kCenter,
                 VAlign::kBottom, kTextColor);
  }
  if (!y_label.empty()) {
    painter.Text(y_label, style.label_px(), cell.x + pad, plot.y + plot.h / 2, HAlign::kCenter, VAlign::kTop,
                 kTextColor, /*vertical=*/true);
  }
  DrawLegend(painter, legend_entries_, plot, legend, style);
}

void Axes::DrawData(Painter& painter, const Style& style) const {
  const AxesLayout& L = layout_;
  for (const auto& s : spans_) {
    const double x0 = L.ToPixel(s.x0, 0).x(), x1 = L.ToPixel(s.x1, 0).x();
    // At least one pixel wide, so that a single flagged sample stays visible.
    const double w = std::max(x1 - x0, 1.0);
    painter.FillRect({x0, L.plot.y, w, L.plot.h}, s.color);
  }
  for (const auto& b : boxes_) {
    const double x0 = L.ToPixel(b.x - b.half_width, 0).x(), x1 = L.ToPixel(b.x + b.half_width, 0).x();
    const double xc = (x0 + x1) / 2, lw = style.line_px() * 0.8;
    const double y_q1 = L.ToPixel(0, b.stats.q1).y(), y_q3 = L.ToPixel(0, b.stats.q3).y();
    const double y_med = L.ToPixel(0, b.stats.median).y();
    const double y_lo = L.ToPixel(0, b.stats.whisker_lo).y(), y_hi = L.ToPixel(0, b.stats.whisker_hi).y();
    painter.FillRect({x0, y_q3, x1 - x0, y_q1 - y_q3}, b.color.WithAlpha(0.45f));
    painter.StrokeRect({x0, y_q3, x1 - x0, y_q1 - y_q3}, b.color, lw);
    painter.Polyline({{xc, y_q3}, {xc, y_hi}}, b.color, lw);
    painter.Polyline({{xc, y_q1}, {xc, y_lo}}, b.color, lw);
    const double cap = (x1 - x0) / 4;
    painter.Polyline({{xc - cap, y_hi}, {xc + cap, y_hi}}, b.color, lw);
    painter.Polyline({{xc - cap, y_lo}, {xc + cap, y_lo}}, b.color, lw);
    painter.Polyline({{x0, y_med}, {x1, y_med}}, kBlack, lw * 1.3);
  }
  for (const auto& l : lines_) {
    std::vector<Eigen::Vector2d> points;
    points.reserve(l.x.size());
    for (std::size_t i = 0; i < l.x.size() && i < l.y.size(); ++i) {
      if (std::isfinite(l.x[i]) && std::isfinite(l.y[i])) points.push_back(L.ToPixel(l.x[i], l.y[i]));
    }
    painter.Polyline(points, l.color, style.line_px() * l.width_scale, l.dashed ? 8.0 * style.scale : 0.0);
  }
  for (const auto& s : scatters_) {
    std::vector<Eigen::Vector2d> centers;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) centers.push_back(L.ToPixel(s.x[i], s.y[i]));
    }
    painter.Discs(centers, 3.5 * style.scale * s.radius_scale, s.color);
  }
}

}  // namespace vigil::plots
