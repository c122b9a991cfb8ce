// Sizes and colours shared by every figure, scaled with the figure's size.
#pragma once

#include <algorithm>
#include <cmath>

#include "plots/image.h"

namespace vigil::plots {

// Text sizes and line widths at the reference size 1600 x 1000, multiplied by `scale`.
struct Style {
  double scale = 1.0;

  int title_px() const { return Px(30); }
  int axes_title_px() const { return Px(21); }
  int label_px() const { return Px(18); }
  int tick_px() const { return Px(15); }
  int legend_px() const { return Px(15); }
  double line_px() const { return 2.2 * scale; }
  double frame_px() const { return std::max(1.0, 1.2 * scale); }
  double tick_len_px() const { return 6.0 * scale; }
  double pad_px() const { return 8.0 * scale; }

  static Style ForSize(int width, int height) {
    return Style{std::clamp(std::min(width / 1600.0, height / 1000.0), 0.25, 8.0)};
  }

 private:
  int Px(double base) const { return std::max(6, static_cast<int>(std::lround(base * scale))); }
};

inline constexpr Color kBlack{0.0f, 0.0f, 0.0f, 1.0f};
inline constexpr Color kFrameColor{0.15f, 0.15f, 0.15f, 1.0f};
inline constexpr Color kGridColor{0.88f, 0.88f, 0.88f, 1.0f};
inline constexpr Color kTextColor{0.1f, 0.1f, 0.1f, 1.0f};

// A colour-blind-safe categorical palette (Okabe and Ito); index wraps around.
Color PaletteColor(int index);

}  // namespace vigil::plots
