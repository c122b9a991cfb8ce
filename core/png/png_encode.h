// 8-bit PNG files in memory, written with libpng: the camera images (sim/, `vigil import`) and the figures
// (plots/). A library of its own (vigil_png) so that what links only vigil_core (vigil-eval) does not depend
// on libpng, and so that no run loads OpenCV's image codecs (with their GDAL, HDF5 and Poppler, 40 MB of a
// process's memory) to write a PNG.
#pragma once

#include <cstdint>
#include <string>

namespace vigil {

// The row filters libpng may choose from: all five, chosen row by row (libpng's default, the smallest files),
// or only Sub and Up (the figures: their flat areas compress as well, at a fraction of the time).
enum class PngFilters { kAdaptive, kSubUp };

// How the pixels of a row are laid out: 1 byte (gray), 3 (RGB), or 4 of which the fourth is not written
// (RGBA or RGBX rows written as RGB, the figures' images).
enum class PngRows { kGray, kRgb, kRgbx };

struct PngEncoding {
  int compression_level = 6;  // zlib's level, 0-9
  PngFilters filters = PngFilters::kAdaptive;
};

// Encodes `height` rows of `width` pixels laid out as `rows` says, top first, row r at
// pixels + r * row_stride_bytes. std::runtime_error("png: ...") when libpng fails or the sizes are invalid.
std::string EncodePng8(const uint8_t* pixels, int width, int height, PngRows rows,
                       std::size_t row_stride_bytes, const PngEncoding& encoding = {});

}  // namespace vigil
