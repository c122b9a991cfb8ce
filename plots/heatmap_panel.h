// A heat-map panel: a grid of coloured cells with their values printed, row labels on the left, column
// labels below (for glitch-sweep maps: ATE ratios per cell).
#pragma once

#include <string>
#include <vector>

#include "plots/panel.h"

namespace vigil::plots {

class HeatmapPanel : public Panel {
 public:
  std::string title, x_label, y_label;
  std::vector<std::string> rows, columns;  // rows top to bottom
  std::vector<double> values;              // rows x columns, row-major; NaN: no value (grey)
  std::vector<std::string> texts;          // printed in each cell (same layout)
  // Colour scale on log(value): `good` (and below) green, `bad` (and above) red, white in between at the
  // geometric midpoint.
  double good = 1.0, bad = 3.0;

  void Draw(Painter& painter, const Rect& cell, const Style& style) override;
};

}  // namespace vigil::plots
