// A panel of a figure: something that draws itself into a cell rectangle (2-D axes, 3-D view).
#pragma once

#include "plots/painter.h"
#include "plots/style.h"

namespace vigil::plots {

class Panel {
 public:
  virtual ~Panel() = default;
  virtual void Draw(Painter& painter, const Rect& cell, const Style& style) = 0;
};

}  // namespace vigil::plots
