// PNG encoding: what is written decodes (with libpng's own reader) to the same pixels, for gray, RGB and RGBX
// rows with padding between them; the zlib level is the one asked for; bad sizes are refused.
#include "core/png/png_encode.h"

#include <png.h>

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace vigil {
namespace {

std::vector<uint8_t> Decode(const std::string& bytes, png_uint_32 format, int* width, int* height) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  EXPECT_TRUE(png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) << image.message;
  image.format = format;
  std::vector<uint8_t> pixels(PNG_IMAGE_SIZE(image));
  EXPECT_TRUE(png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) << image.message;
  *width = static_cast<int>(image.width);
  *height = static_cast<int>(image.height);
  return pixels;
}

TEST(PngEncode, GrayAndRgbRowsDecodeToTheSamePixels) {
  constexpr int kWidth = 7, kHeight = 5, kStride = 10;  // rows padded to 10 bytes (gray)
  std::vector<uint8_t> gray(kStride * kHeight, 0xEE);
  std::vector<uint8_t> packed_gray;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      packed_gray.push_back(gray[y * kStride + x] = static_cast<uint8_t>(x * 31 + y * 7));
  int w = 0, h = 0;
  EXPECT_EQ(
      Decode(EncodePng8(gray.data(), kWidth, kHeight, PngRows::kGray, kStride), PNG_FORMAT_GRAY, &w, &h),
      packed_gray);
  EXPECT_EQ(w, kWidth);
  EXPECT_EQ(h, kHeight);

  std::vector<uint8_t> rgb(kWidth * 3 * kHeight);
  for (std::size_t k = 0; k < rgb.size(); ++k) rgb[k] = static_cast<uint8_t>(k * 13);
  const std::string rgb_png =
      EncodePng8(rgb.data(), kWidth, kHeight, PngRows::kRgb, kWidth * 3, {9, PngFilters::kSubUp});
  EXPECT_EQ(Decode(rgb_png, PNG_FORMAT_RGB, &w, &h), rgb);

  // The same pixels with a fourth byte each: that byte is not written, so the file is the RGB one.
  std::vector<uint8_t> rgbx;
  for (std::size_t k = 0; k < rgb.size(); k += 3)
    rgbx.insert(rgbx.end(), {rgb[k], rgb[k + 1], rgb[k + 2], 0x55});
  EXPECT_EQ(EncodePng8(rgbx.data(), kWidth, kHeight, PngRows::kRgbx, kWidth * 4, {9, PngFilters::kSubUp}),
            rgb_png);
}

TEST(PngEncode, TheCompressionLevelIsTheOneAskedFor) {
  std::vector<uint8_t> gray(64 * 64);
  for (std::size_t k = 0; k < gray.size(); ++k) gray[k] = static_cast<uint8_t>((k / 64) % 4 * 60);
  const std::string stored = EncodePng8(gray.data(), 64, 64, PngRows::kGray, 64, {0});
  const std::string best = EncodePng8(gray.data(), 64, 64, PngRows::kGray, 64, {9});
  EXPECT_GT(stored.size(), gray.size());  // level 0 stores the rows
  EXPECT_LT(best.size(), gray.size() / 10);
}

TEST(PngEncode, BadSizesAreRefused) {
  const std::vector<uint8_t> pixels(100);
  EXPECT_THROW(EncodePng8(pixels.data(), 0, 3, PngRows::kGray, 3), std::runtime_error);
  EXPECT_THROW(EncodePng8(pixels.data(), 3, 3, PngRows::kRgbx, 9),
               std::runtime_error);  // rows of 12 bytes, 9 apart
  EXPECT_THROW(EncodePng8(pixels.data(), 3, 3, PngRows::kRgb, 8),
               std::runtime_error);  // rows of 9 bytes, 8 apart
  EXPECT_THROW(EncodePng8(pixels.data(), 3, 3, PngRows::kGray, 3, {10}), std::runtime_error);
}

}  // namespace
}  // namespace vigil
