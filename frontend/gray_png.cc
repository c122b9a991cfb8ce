#include "frontend/gray_png.h"

#include <png.h>

#include <csetjmp>
#include <cstring>
#include <vector>

#include "core/error.h"

namespace vigil::frontend {
namespace {

// libpng reports an error by calling PngError, which must not return: it longjmps back to the setjmp in
// DecodeGrayPng (exceptions must not cross libpng's C frames). Warnings are dropped: a decode either
// succeeds or fails with the error's message.
struct DecodeState {
  const std::string* bytes = nullptr;
  std::size_t offset = 0;
  std::string error;
};

void PngError(png_structp png, png_const_charp message) {
  static_cast<DecodeState*>(png_get_error_ptr(png))->error = message ? message : "unknown error";
  png_longjmp(png, 1);
}
void PngWarning(png_structp, png_const_charp) {}

void ReadFromBytes(png_structp png, png_bytep data, png_size_t length) {
  auto* state = static_cast<DecodeState*>(png_get_io_ptr(png));
  if (length > state->bytes->size() - state->offset) png_error(png, "truncated file");
  std::memcpy(data, state->bytes->data() + state->offset, length);
  state->offset += length;
}

std::string FormatName(int bit_depth, int color_type) {
  switch (color_type) {
    case PNG_COLOR_TYPE_GRAY:
      return std::to_string(bit_depth) + "-bit grayscale";
    case PNG_COLOR_TYPE_GRAY_ALPHA:
      return "grayscale + alpha";
    case PNG_COLOR_TYPE_RGB:
      return "RGB";
    case PNG_COLOR_TYPE_RGB_ALPHA:
      return "RGBA";
    case PNG_COLOR_TYPE_PALETTE:
      return "palette";
    default:
      return "unknown colour type";
  }
}

// One line, printable.
std::string Printable(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return s;
}

}  // namespace

cv::Mat DecodeGrayPng(const std::string& bytes) {
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0)
    throw InputError("not a PNG file (cam0 images must be 8-bit grayscale PNG)");
  DecodeState state;
  state.bytes = &bytes;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, PngError, PngWarning);
  if (png == nullptr) throw std::runtime_error("png: cannot create a reader");
  png_infop info = png_create_info_struct(png);
  // Declared before setjmp and only assigned outside the jump's reach: what the error path must know.
  std::string refusal;
  cv::Mat image;
  std::vector<png_bytep> rows;
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw InputError("corrupt PNG: " + Printable(state.error));
  }
  png_set_read_fn(png, &state, ReadFromBytes);
  png_set_user_limits(png, 1 << 16, 1 << 16);
  png_read_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
  const int bit_depth = png_get_bit_depth(png, info), color_type = png_get_color_type(png, info);
  if (color_type != PNG_COLOR_TYPE_GRAY || bit_depth != 8)
    refusal = FormatName(bit_depth, color_type) + " PNG: cam0 images must be 8-bit grayscale";
  else if (static_cast<int64_t>(width) * static_cast<int64_t>(height) > kMaxImagePixels)
    refusal = std::to_string(width) + " x " + std::to_string(height) + " px: more than " +
              std::to_string(kMaxImagePixels) + " pixels";
  if (refusal.empty()) {
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != width) png_error(png, "unexpected row layout");
    image.create(static_cast<int>(height), static_cast<int>(width), CV_8UC1);
    rows.resize(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = image.ptr<png_byte>(static_cast<int>(y));
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  if (!refusal.empty()) throw InputError(refusal);
  return image;
}

}  // namespace vigil::frontend
