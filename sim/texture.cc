#include "sim/texture.h"

#include <algorithm>

#include "core/random.h"

namespace vigil::sim {
namespace {

void FillWrapped(GrayTexture* t, int x0, int y0, int w, int h, const std::vector<uint8_t>& levels, int cell) {
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int level = cell > 0 ? ((x / cell + y / cell) % 2) : 0;
      t->gray[static_cast<std::size_t>((y0 + y) % t->size) * t->size + (x0 + x) % t->size] = levels[level];
    }
}

}  // namespace

std::vector<GrayTexture> MakeTextures(int count, int size, uint64_t seed) {
  Rng rng(seed, "texture");
  std::vector<GrayTexture> out;
  for (int i = 0; i < count; ++i) {
    GrayTexture t;
    t.size = size;
    t.gray.assign(static_cast<std::size_t>(size) * size, 128);
    const auto level = [&] { return static_cast<uint8_t>(20 + rng.UniformIndex(216)); };
    // Rectangles from large to small, so that small detail stays on top: about 1 per (size / 12)^2 area.
    const int rects = std::max(8, size * size / 2200);
    for (int k = 0; k < rects; ++k) {
      const double scale = 1.0 - static_cast<double>(k) / rects;
      const int max_side = std::max(3, static_cast<int>(size * (0.04 + 0.2 * scale)));
      const int w = 2 + static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(max_side)));
      const int h = 2 + static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(max_side)));
      const int x0 = static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(size)));
      const int y0 = static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(size)));
      FillWrapped(&t, x0, y0, w, h, {level()}, 0);
    }
    // A few checkerboard patches.
    for (int k = 0; k < 6; ++k) {
      const int cell = std::max(2, size / 64) +
                       static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(std::max(2, size / 48))));
      const int side = cell * (4 + 2 * static_cast<int>(rng.UniformIndex(3)));
      const int x0 = static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(size)));
      const int y0 = static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(size)));
      const uint8_t a = level(), b = level();
      FillWrapped(&t, x0, y0, std::min(side, size), std::min(side, size), {a, b}, cell);
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace vigil::sim
