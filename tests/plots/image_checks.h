// Pixel predicates for figure tests.
#pragma once

#include <cmath>

#include "plots/image.h"
#include "plots/painter.h"

namespace vigil::plots::testing {

inline const uint8_t* At(const Image& image, double x, double y) {
  return image.Pixel(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
}
inline bool IsWhite(const Image& image, double x, double y) {
  const uint8_t* p = At(image, x, y);
  return p[0] > 245 && p[1] > 245 && p[2] > 245;
}
inline bool IsReddish(const Image& image, double x, double y) {
  const uint8_t* p = At(image, x, y);
  return p[0] > 200 && p[1] < 120 && p[2] < 120;
}
inline bool IsBluish(const Image& image, double x, double y) {
  const uint8_t* p = At(image, x, y);
  return p[2] > 150 && p[0] < 140 && p[1] < 140;
}
// Pixels inside `r` with a colour strictly between pure red and white (anti-aliasing).
inline int CountPartialRed(const Image& image, const Rect& r) {
  int n = 0;
  for (int y = static_cast<int>(r.y); y < static_cast<int>(r.bottom()); ++y) {
    for (int x = static_cast<int>(r.x); x < static_cast<int>(r.right()); ++x) {
      const uint8_t* p = image.Pixel(x, y);
      if (p[0] > 200 && p[1] == p[2] && p[1] > 40 && p[1] < 215) ++n;
    }
  }
  return n;
}
// Dark (text-like) pixels inside `r`, clipped to the image.
inline int CountDark(const Image& image, const Rect& r) {
  int n = 0;
  for (int y = std::max(0, static_cast<int>(r.y)); y < std::min(image.height, static_cast<int>(r.bottom()));
       ++y) {
    for (int x = std::max(0, static_cast<int>(r.x)); x < std::min(image.width, static_cast<int>(r.right()));
         ++x) {
      const uint8_t* p = image.Pixel(x, y);
      if (p[0] < 100 && p[1] < 100 && p[2] < 100) ++n;
    }
  }
  return n;
}

// Pixels that differ between two images of the same size (-1 when the sizes differ).
inline int CountDifferentPixels(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return -1;
  int n = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    if (a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2]) ++n;
  }
  return n;
}

}  // namespace vigil::plots::testing
