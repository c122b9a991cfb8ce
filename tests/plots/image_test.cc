#include "plots/image.h"

#include <gtest/gtest.h>

namespace vigil::plots {
namespace {

TEST(Image, PngRoundTripKeepsPixels) {
  Image image(7, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) {
      uint8_t* p = image.Pixel(x, y);
      p[0] = static_cast<uint8_t>(x * 30);
      p[1] = static_cast<uint8_t>(y * 50);
      p[2] = static_cast<uint8_t>(x * y);
    }
  }
  const std::string png = EncodePng(image);
  const Image back = DecodePng(png);
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  EXPECT_EQ(back.rgba, image.rgba);
  EXPECT_EQ(EncodePng(back), png);  // deterministic bytes
}

TEST(Image, DecodeRejectsGarbage) {
  EXPECT_THROW(DecodePng("not a png"), std::runtime_error);
  Image image(4, 4);
  std::string png = EncodePng(image);
  png.resize(png.size() / 2);
  EXPECT_THROW(DecodePng(png), std::runtime_error);
}

TEST(Image, BlendMixesByCoverage) {
  Image image(1, 1);  // white
  image.Blend(0, 0, Color{0.0f, 0.0f, 0.0f, 1.0f}, 0.5f);
  EXPECT_NEAR(image.Pixel(0, 0)[0], 128, 1);
  image.Blend(5, 5, Color{}, 1.0f);  // outside: ignored
  EXPECT_NEAR(image.Pixel(0, 0)[0], 128, 1);
}

}  // namespace
}  // namespace vigil::plots
