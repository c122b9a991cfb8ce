// An RGBA raster image and its PNG encoding.
//
// Rows are stored top first, 4 bytes per pixel (r, g, b, a). EncodePng writes 8-bit RGB (the figures are
// opaque) with fixed zlib settings and no time chunk, so the same image always gives the same bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vigil::plots {

// A colour with components in [0, 1].
struct Color {
  float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;

  Color WithAlpha(float alpha) const { return {r, g, b, alpha}; }
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4, top row first

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 255) {}

  uint8_t* Pixel(int x, int y) { return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4; }
  const uint8_t* Pixel(int x, int y) const {
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
  }
  // Alpha-blends `color` with extra coverage `coverage` in [0, 1] over pixel (x, y) (ignored outside).
  void Blend(int x, int y, const Color& color, float coverage);
};

// PNG bytes of `image` (8-bit RGB, alpha dropped).
std::string EncodePng(const Image& image);
// Decodes PNG bytes (any colour type libpng can expand to 8-bit RGBA); std::runtime_error on bad data.
Image DecodePng(const std::string& bytes);
// Writes `image` as PNG to `path` atomically (core/output.h).
void WritePng(const std::filesystem::path& path, const Image& image);

}  // namespace vigil::plots
