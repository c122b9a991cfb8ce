// Decoding a camera image file: an 8-bit grayscale PNG (EuRoC's cam0 format, and what `vigil simulate
// --images` writes) into a CV_8UC1 matrix. Nothing else is converted (docs/safety.md, "Images"): a 16-bit,
// colour, palette, alpha or low-bit-depth PNG, or a file that is not a PNG, is refused, so that a recording
// in another format is never tracked on silently converted pixels. libpng's own messages become the reason
// of the one error, never text printed on stderr.
#pragma once

#include <cstdint>
#include <string>

#include <opencv2/core/mat.hpp>

namespace vigil::frontend {

// The most pixels an image may have (a 16k x 16k image); a header claiming more is refused before any
// allocation.
inline constexpr int64_t kMaxImagePixels = int64_t{1} << 28;

// Decodes `bytes`; InputError with a one-line reason ("not a PNG file", "16-bit PNG: cam0 images must be
// 8-bit grayscale", "corrupt PNG: <libpng's message>", ...).
cv::Mat DecodeGrayPng(const std::string& bytes);

}  // namespace vigil::frontend
