#include "plots/figure.h"

#include <stdexcept>

#include "plots/painter.h"
#include "plots/style.h"

namespace vigil::plots {

Figure::Figure(int rows, int cols, std::string title) : rows_(rows), cols_(cols), title_(std::move(title)) {
  if (rows <= 0 || cols <= 0) throw std::invalid_argument("Figure: the grid needs at least one cell");
}

template <class P>
P& Figure::Add(int row, int col, int row_span, int col_span) {
  auto panel = std::make_unique<P>();
  P& ref = *panel;
  AddPanel(std::move(panel), row, col, row_span, col_span);
  return ref;
}

Panel& Figure::AddPanel(std::unique_ptr<Panel> panel, int row, int col, int row_span, int col_span) {
  if (row < 0 || col < 0 || row_span < 1 || col_span < 1 || row + row_span > rows_ ||
      col + col_span > cols_) {
    throw std::invalid_argument("Figure: panel outside the grid");
  }
  Panel& ref = *panel;
  panels_.push_back({std::move(panel), row, col, row_span, col_span});
  return ref;
}

Axes& Figure::AddAxes(int row, int col, int row_span, int col_span) {
  return Add<Axes>(row, col, row_span, col_span);
}

Axes3D& Figure::AddAxes3D(int row, int col, int row_span, int col_span) {
  return Add<Axes3D>(row, col, row_span, col_span);
}

Axes* Figure::axes(int index) {
  if (index < 0 || index >= static_cast<int>(panels_.size())) return nullptr;
  return dynamic_cast<Axes*>(panels_[index].panel.get());
}

Rect Figure::CellRect(int width, int height, int row, int col, int row_span, int col_span) const {
  const Style style = Style::ForSize(width, height);
  const double margin = 2.0 * style.pad_px();
  const double top = margin + (title_.empty() ? 0.0 : style.title_px() * 1.6);
  const double cell_w = (width - 2.0 * margin) / cols_, cell_h = (height - top - margin) / rows_;
  return {margin + col * cell_w, top + row * cell_h, col_span * cell_w, row_span * cell_h};
}

Image Figure::Render(gl::GlContext* gl, TextRenderer* text, int width, int height) {
  const Style style = Style::ForSize(width, height);
  Painter painter(gl, text, width, height);
  if (!title_.empty()) {
    painter.Text(title_, style.title_px(), width / 2.0, 2.0 * style.pad_px(), HAlign::kCenter, VAlign::kTop,
                 kTextColor);
  }
  for (Placed& p : panels_) {
    p.panel->Draw(painter, CellRect(width, height, p.row, p.col, p.row_span, p.col_span), style);
  }
  return painter.Finish();
}

}  // namespace vigil::plots
