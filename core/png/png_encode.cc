#include "core/png/png_encode.h"

#include <png.h>

#include <csetjmp>
#include <stdexcept>

#include "core/png/png_errors.h"

namespace vigil {
namespace {

void AppendToString(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}
void FlushNothing(png_structp) {}

}  // namespace

std::string EncodePng8(const uint8_t* pixels, int width, int height, PngRows rows,
                       std::size_t row_stride_bytes, const PngEncoding& encoding) {
  if (width <= 0 || height <= 0) throw std::runtime_error("png: empty image");
  const int channels = rows == PngRows::kGray ? 1 : rows == PngRows::kRgb ? 3 : 4;
  if (row_stride_bytes < static_cast<std::size_t>(width) * static_cast<std::size_t>(channels))
    throw std::runtime_error("png: rows overlap");
  if (encoding.compression_level < 0 || encoding.compression_level > 9)
    throw std::runtime_error("png: compression level " + std::to_string(encoding.compression_level) +
                             " is not in 0-9");
  std::string out;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, png_errors::RecordAndJump, png_errors::Ignore);
  if (png == nullptr) throw std::runtime_error("png: cannot create writer");
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("png: cannot encode: " + png_errors::Last());
  }
  png_set_write_fn(png, &out, AppendToString, FlushNothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               rows == PngRows::kGray ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, encoding.compression_level);
  if (encoding.filters == PngFilters::kSubUp) png_set_filter(png, 0, PNG_FILTER_SUB | PNG_FILTER_UP);
  png_write_info(png, info);
  if (rows == PngRows::kRgbx) png_set_filler(png, 0, PNG_FILLER_AFTER);  // the fourth byte is not written
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(pixels + static_cast<std::size_t>(y) * row_stride_bytes));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

}  // namespace vigil
