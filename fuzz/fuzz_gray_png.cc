// libFuzzer target: a camera image file (DecodeGrayPng, as `vigil track` and `vigil run --dataset` read
// cam0/data/*.png). An accepted image is 8-bit single-channel with the size its header gave.
#include "frontend/gray_png.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  vigil::fuzz::ExpectOnlyInputErrors([&] {
    const cv::Mat image = vigil::frontend::DecodeGrayPng(bytes);
    if (image.type() != CV_8UC1 || image.empty()) std::abort();
  });
  return 0;
}
