// A figure: a title over a grid of panels (2-D axes or 3-D views), rendered to an image.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gl/gl_context.h"
#include "plots/axes.h"
#include "plots/axes3d.h"
#include "plots/image.h"
#include "plots/text.h"

namespace vigil::plots {

class Figure {
 public:
  // A grid of rows x cols cells.
  Figure(int rows, int cols, std::string title = "");

  // Adds a panel at (row, col) spanning row_span x col_span cells.
  Axes& AddAxes(int row, int col, int row_span = 1, int col_span = 1);
  Axes3D& AddAxes3D(int row, int col, int row_span = 1, int col_span = 1);
  // Adds a panel of another kind (e.g. heatmap_panel.h) at (row, col); returns it.
  Panel& AddPanel(std::unique_ptr<Panel> panel, int row, int col, int row_span = 1, int col_span = 1);

  // Draws every panel into a width x height image.
  Image Render(gl::GlContext* gl, TextRenderer* text, int width, int height);

  // The pixel rectangle of a cell span in a width x height rendering.
  Rect CellRect(int width, int height, int row, int col, int row_span = 1, int col_span = 1) const;

  const std::string& title() const { return title_; }
  // The index-th panel added, as 2-D axes (null when it is a 3-D view or out of range).
  Axes* axes(int index);

 private:
  struct Placed {
    std::unique_ptr<Panel> panel;
    int row, col, row_span, col_span;
  };
  template <class P>
  P& Add(int row, int col, int row_span, int col_span);

  int rows_, cols_;
  std::string title_;
  std::vector<Placed> panels_;
};

}  // namespace vigil::plots
