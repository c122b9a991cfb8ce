#include "plots/glitch_map_figure.h"

#include <cmath>
#include <memory>

#include "core/format.h"
#include "plots/figure_png.h"
#include "plots/heatmap_panel.h"

namespace vigil::plots {

Figure GlitchMapFigure(const experiments::GlitchMap& map, const std::string& title) {
  const int n = std::max<int>(1, static_cast<int>(map.methods.size()));
  const int cols = n <= 3 ? n : (n + 1) / 2;
  const int rows = (n + cols - 1) / cols;
  Figure figure(rows, cols, title);
  for (int m = 0; m < static_cast<int>(map.methods.size()); ++m) {
    auto panel = std::make_unique<HeatmapPanel>();
    panel->title = map.methods[m];
    panel->x_label = map.column_axis;
    panel->y_label = map.row_axis;
    panel->rows = map.rows;
    panel->columns = map.columns;
    for (std::size_t r = 0; r < map.rows.size(); ++r) {
      for (std::size_t c = 0; c < map.columns.size(); ++c) {
        const experiments::MapCell& cell = map.Cell(static_cast<std::size_t>(m), r, c);
        panel->values.push_back(cell.ratio);
        panel->texts.push_back(cell.failed > 0             ? std::to_string(cell.failed) + " failed"
                               : std::isfinite(cell.ratio) ? FormatFixed(cell.ratio, 2)
                                                           : std::string("-"));
      }
    }
    panel->good = 1.0;
    panel->bad = 3.0;
    figure.AddPanel(std::move(panel), m / cols, m % cols);
  }
  return figure;
}

void WriteGlitchMapFigure(const experiments::GlitchMap& map, const std::string& title,
                          const std::filesystem::path& path, const FigureOptions& options) {
  WriteFigurePng(GlitchMapFigure(map, title), path, options);
}

}  // namespace vigil::plots
