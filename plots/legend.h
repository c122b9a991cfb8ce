// A legend box in a corner of a plot area: one row per labelled series (line, marker or filled patch).
#pragma once

#include <string>
#include <vector>

#include "plots/painter.h"
#include "plots/style.h"

namespace vigil::plots {

enum class LegendKind { kLine, kMarker, kPatch };

struct LegendEntry {
  std::string label;
  Color color;
  LegendKind kind = LegendKind::kLine;
  bool dashed = false;
};

enum class LegendPosition { kNone, kUpperRight, kUpperLeft, kLowerRight, kLowerLeft, kOutsideRight };

// Draws the entries with a non-empty label inside `area` at `position` (kOutsideRight: to the right of
// `area`, top-aligned; the caller leaves room with LegendWidth()).
void DrawLegend(Painter& painter, const std::vector<LegendEntry>& entries, const Rect& area,
                LegendPosition position, const Style& style);

// Width of the legend box of `entries` [px] (0 when no entry has a label).
double LegendWidth(Painter& painter, const std::vector<LegendEntry>& entries, const Style& style);

}  // namespace vigil::plots
