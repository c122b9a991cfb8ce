#include "core/bag/gray_image.h"

#include <opencv2/imgproc.hpp>

namespace vigil::bag {
namespace {

struct Encoding {
  const char* name;
  int cv_type;
  int to_gray;  // cv::ColorConversionCodes, or -1: already one channel
};

constexpr Encoding kEncodings[] = {
    {"mono8", CV_8UC1, -1},
    {"8UC1", CV_8UC1, -1},
    {"mono16", CV_16UC1, -1},
    {"16UC1", CV_16UC1, -1},
    {"rgb8", CV_8UC3, cv::COLOR_RGB2GRAY},
    {"bgr8", CV_8UC3, cv::COLOR_BGR2GRAY},
    {"rgba8", CV_8UC4, cv::COLOR_RGBA2GRAY},
    {"bgra8", CV_8UC4, cv::COLOR_BGRA2GRAY},
};

const Encoding& FindEncoding(const std::string& name) {
  for (const Encoding& e : kEncodings)
    if (name == e.name) return e;
  throw MessageError("encoding '" + name + "' is not supported (mono8, mono16, rgb8, bgr8, rgba8, bgra8)");
}

}  // namespace

cv::Mat ToGray8(const ImageMessage& image) {
  const Encoding& encoding = FindEncoding(image.encoding);
  if (image.width == 0 || image.height == 0 || image.width > kMaxImageSide || image.height > kMaxImageSide ||
      int64_t{image.width} * image.height > kMaxImagePixels)
    throw MessageError("image of " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                       " px (1 .. 65536 a side, at most 2^28 pixels)");
  const std::size_t row_bytes = std::size_t{image.width} * CV_ELEM_SIZE(encoding.cv_type);
  if (image.step < row_bytes)
    throw MessageError("step " + std::to_string(image.step) + " is shorter than a row of " +
                       std::to_string(row_bytes) + " bytes");
  if (uint64_t{image.step} * image.height != image.size)
    throw MessageError("data holds " + std::to_string(image.size) + " bytes, step x height is " +
                       std::to_string(uint64_t{image.step} * image.height));
  // A view of the message's bytes; nothing is written through it.
  cv::Mat raw(static_cast<int>(image.height), static_cast<int>(image.width), encoding.cv_type,
              const_cast<uint8_t*>(image.data), image.step);
  cv::Mat gray;
  if (encoding.cv_type == CV_16UC1) {
    cv::Mat native = raw;
    if (image.big_endian) {  // the host is little-endian (x86-64, arm64)
      native = raw.clone();
      for (int r = 0; r < native.rows; ++r) {
        uint16_t* row = native.ptr<uint16_t>(r);
        for (int c = 0; c < native.cols; ++c) row[c] = static_cast<uint16_t>(row[c] << 8 | row[c] >> 8);
      }
    }
    native.convertTo(gray, CV_8U, 1.0 / 257.0);
  } else if (encoding.to_gray >= 0) {
    cv::cvtColor(raw, gray, encoding.to_gray);
  } else {
    gray = raw.clone();
  }
  return gray;
}

}  // namespace vigil::bag
