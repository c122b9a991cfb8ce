#include "plots/legend.h"

#include <algorithm>

namespace vigil::plots {
namespace {

// The entries to show: labelled ones, each label once (many spans or boxes may share one label).
std::vector<const LegendEntry*> Shown(const std::vector<LegendEntry>& entries) {
  std::vector<const LegendEntry*> shown;
  for (const LegendEntry& e : entries) {
    if (e.label.empty()) continue;
    const bool seen =
        std::any_of(shown.begin(), shown.end(), [&](const LegendEntry* s) { return s->label == e.label; });
    if (!seen) shown.push_back(&e);
  }
  return shown;
}

double SymbolWidth(const Style& style) { return 34.0 * style.scale; }
double RowHeight(const Style& style) { return style.legend_px() * 1.45; }

}  // namespace

double LegendWidth(Painter& painter, const std::vector<LegendEntry>& entries, const Style& style) {
  const std::vector<const LegendEntry*> shown = Shown(entries);
  double text_w = 0.0;
  for (const LegendEntry* e : shown) {
    text_w = std::max(text_w, static_cast<double>(painter.MeasureText(e->label, style.legend_px()).width));
  }
  return !shown.empty() ? text_w + SymbolWidth(style) + 3.0 * style.pad_px() : 0.0;
}

void DrawLegend(Painter& painter, const std::vector<LegendEntry>& entries, const Rect& area,
                LegendPosition position, const Style& style) {
  const std::vector<const LegendEntry*> shown = Shown(entries);
  if (shown.empty() || position == LegendPosition::kNone) return;
  const double pad = style.pad_px(), row_h = RowHeight(style);
  const double w = LegendWidth(painter, entries, style), h = row_h * shown.size() + pad;
  const double margin = 1.5 * pad;
  double x = area.right() - w - margin, y = area.y + margin;
  switch (position) {
    case LegendPosition::kUpperLeft:
      x = area.x + margin;
      break;
    case LegendPosition::kLowerRight:
      y = area.bottom() - h - margin;
      break;
    case LegendPosition::kLowerLeft:
      x = area.x + margin;
      y = area.bottom() - h - margin;
      break;
    case LegendPosition::kOutsideRight:
      x = area.right() + margin;
      break;
    default:
      break;
  }
  const Rect box{x, y, w, h};
  painter.FillRect(box, Color{1.0f, 1.0f, 1.0f, 0.9f});
  painter.StrokeRect(box, Color{0.7f, 0.7f, 0.7f, 1.0f}, style.frame_px());
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const LegendEntry& e = *shown[i];
    const double cy = y + pad / 2 + row_h * (i + 0.5);
    const double sx0 = x + pad, sx1 = sx0 + SymbolWidth(style);
    switch (e.kind) {
      case LegendKind::kLine:
        painter.Polyline({{sx0, cy}, {sx1, cy}}, e.color, style.line_px(),
                         e.dashed ? 6.0 * style.scale : 0.0);
        break;
      case LegendKind::kMarker:
        painter.Discs({{(sx0 + sx1) / 2, cy}}, 4.5 * style.scale, e.color);
        break;
      case LegendKind::kPatch:
        painter.FillRect({sx0, cy - row_h * 0.3, sx1 - sx0, row_h * 0.6}, e.color);
        break;
    }
    painter.Text(e.label, style.legend_px(), sx1 + pad, cy, HAlign::kLeft, VAlign::kMiddle, kTextColor);
  }
}

}  // namespace vigil::plots
