// Figure 2: one IMU axis with and without injected glitches, one panel per glitch setting.
#include "plots/figures.h"
#include "plots/style.h"

namespace vigil::plots {

Figure GlitchFigure(const std::vector<ImuTrace>& panels) {
  const int n = std::max<int>(1, static_cast<int>(panels.size()));
  Figure figure(n, 1, "IMU glitches: measurement with and without injected noise");
  for (int i = 0; i < static_cast<int>(panels.size()); ++i) {
    const ImuTrace& p = panels[i];
    Axes& axes = figure.AddAxes(i, 0);
    axes.title = p.label;
    axes.y_label = p.axis_name + " [" + p.unit + "]";
    if (i + 1 == n) axes.x_label = "time [s]";
    axes.Line(p.t_s, p.measured, PaletteColor(1), "with glitches", 0.6);
    axes.Line(p.t_s, p.clean, PaletteColor(0), "without glitches", 0.8);
    axes.legend = i == 0 ? LegendPosition::kUpperRight : LegendPosition::kNone;
  }
  return figure;
}

}  // namespace vigil::plots
