#include "plots/heatmap_panel.h"

#include <algorithm>
#include <cmath>

namespace vigil::plots {
namespace {

Color Mix(const Color& a, const Color& b, double s) {
  const auto f = static_cast<float>(std::clamp(s, 0.0, 1.0));
  return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f, 1.0f};
}

Color ScaleColor(double value, double good, double bad) {
  constexpr Color kGood{0.55f, 0.80f, 0.55f, 1.0f}, kMid{1.0f, 1.0f, 0.92f, 1.0f},
      kBad{0.90f, 0.40f, 0.35f, 1.0f};
  if (!std::isfinite(value)) return {0.8f, 0.8f, 0.8f, 1.0f};
  const double s = (std::log(std::max(value, 1e-12)) - std::log(good)) / (std::log(bad) - std::log(good));
  return s < 0.5 ? Mix(kGood, kMid, 2.0 * s) : Mix(kMid, kBad, 2.0 * s - 1.0);
}

}  // namespace

void HeatmapPanel::Draw(Painter& painter, const Rect& cell, const Style& style) {
  const double pad = style.pad_px();
  const double left = cell.x + pad + 0.16 * cell.w, right = cell.right() - pad;
  const double top = cell.y + pad + 1.8 * style.axes_title_px(),
               bottom = cell.bottom() - pad - 2.6 * style.label_px();
  painter.Text(title, style.axes_title_px(), 0.5 * (cell.x + cell.right()), cell.y + pad, HAlign::kCenter,
               VAlign::kTop, kTextColor);
  if (rows.empty() || columns.empty()) return;
  const double w = (right - left) / static_cast<double>(columns.size());
  const double h = (bottom - top) / static_cast<double>(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::size_t i = r * columns.size() + c;
      const Rect box{left + c * w, top + r * h, w, h};
      painter.FillRect(box, ScaleColor(i < values.size() ? values[i] : NAN, good, bad));
      painter.StrokeRect(box, kFrameColor, style.frame_px());
      if (i < texts.size())
        painter.Text(texts[i], style.label_px(), box.x + 0.5 * w, box.y + 0.5 * h, HAlign::kCenter,
                     VAlign::kMiddle, kTextColor);
    }
    painter.Text(rows[r], style.tick_px(), left - pad, top + (r + 0.5) * h, HAlign::kRight, VAlign::kMiddle,
                 kTextColor);
  }
  for (std::size_t c = 0; c < columns.size(); ++c)
    painter.Text(columns[c], style.tick_px(), left + (c + 0.5) * w, bottom + pad, HAlign::kCenter,
                 VAlign::kTop, kTextColor);
  painter.Text(x_label, style.label_px(), 0.5 * (left + right), bottom + pad + 1.4 * style.tick_px(),
               HAlign::kCenter, VAlign::kTop, kTextColor);
  painter.Text(y_label, style.label_px(), cell.x + pad, top - 0.6 * style.label_px(), HAlign::kLeft,
               VAlign::kBottom, kTextColor);
}

}  // namespace vigil::plots
