#include "plots/image.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstring>
#include <stdexcept>

#include "core/output.h"
#include "core/png/png_encode.h"
#include "core/png/png_errors.h"

namespace vigil::plots {
namespace {

struct ReadCursor {
  const std::string* bytes;
  std::size_t offset;
};
void ReadFromString(png_structp png, png_bytep data, png_size_t length) {
  auto* cursor = static_cast<ReadCursor*>(png_get_io_ptr(png));
  if (cursor->offset + length > cursor->bytes->size()) png_error(png, "truncated data");
  std::memcpy(data, cursor->bytes->data() + cursor->offset, length);
  cursor->offset += length;
}

uint8_t ToByte(float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

void Image::Blend(int x, int y, const Color& color, float coverage) {
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  const float a = std::clamp(color.a * coverage, 0.0f, 1.0f);
  if (a <= 0.0f) return;
  uint8_t* p = Pixel(x, y);
  const float c[3] = {color.r, color.g, color.b};
  for (int i = 0; i < 3; ++i) p[i] = ToByte(c[i] * a + (p[i] / 255.0f) * (1.0f - a));
}

std::string EncodePng(const Image& image) {
  return EncodePng8(image.rgba.data(), image.width, image.height, PngRows::kRgbx,
                    static_cast<std::size_t>(image.width) * 4, {6, PngFilters::kSubUp});
}

Image DecodePng(const std::string& bytes) {
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0) {
    throw std::runtime_error("png: not a PNG file");
  }
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, png_errors::RecordAndJump, png_errors::Ignore);
  if (png == nullptr) throw std::runtime_error("png: cannot create reader");
  png_infop info = png_create_info_struct(png);
  ReadCursor cursor{&bytes, 0};
  Image image;
  std::vector<png_bytep> rows;
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw std::runtime_error("png: cannot decode: " + png_errors::Last());
  }
  {
    png_set_read_fn(png, &cursor, ReadFromString);
    png_read_info(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_read_update_info(png, info);
    image = Image(static_cast<int>(png_get_image_width(png, info)),
                  static_cast<int>(png_get_image_height(png, info)));
    if (png_get_rowbytes(png, info) != static_cast<png_size_t>(image.width) * 4) {
      png_error(png, "unexpected row layout");
    }
    rows.resize(image.height);
    for (int y = 0; y < image.height; ++y) rows[y] = image.Pixel(0, y);
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return image;
}

void WritePng(const std::filesystem::path& path, const Image& image) {
  WriteFileAtomic(path, EncodePng(image));
}

}  // namespace vigil::plots
