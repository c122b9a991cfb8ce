#include "frontend/gray_png.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/core/test_util.h"

namespace vigil::frontend {
namespace {
using vigil::testing::InputErrorOf;

std::string Encode(const cv::Mat& image) {
  std::vector<uchar> bytes;
  EXPECT_TRUE(cv::imencode(".png", image, bytes));
  return std::string(bytes.begin(), bytes.end());
}

cv::Mat Ramp(int type) {
  cv::Mat gray(12, 16, CV_8UC1);
  for (int y = 0; y < gray.rows; ++y)
    for (int x = 0; x < gray.cols; ++x) gray.at<uchar>(y, x) = static_cast<uchar>(x * 16 + y);
  cv::Mat out;
  if (type == CV_16UC1)
    gray.convertTo(out, CV_16U, 256);
  else if (type == CV_8UC3)
    cv::merge(std::vector<cv::Mat>{gray, gray, gray}, out);
  else if (type == CV_8UC4)
    cv::merge(std::vector<cv::Mat>{gray, gray, gray, gray}, out);
  else
    out = gray;
  return out;
}

TEST(GrayPng, An8BitGrayscaleImageDecodesToItsPixels) {
  const cv::Mat image = Ramp(CV_8UC1);
  const cv::Mat decoded = DecodeGrayPng(Encode(image));
  ASSERT_EQ(decoded.type(), CV_8UC1);
  EXPECT_EQ(cv::norm(decoded, image, cv::NORM_INF), 0.0);
}

TEST(GrayPng, OtherPixelFormatsAreRefusedNotConverted) {
  EXPECT_EQ(InputErrorOf([] { DecodeGrayPng(Encode(Ramp(CV_16UC1))); }),
            "16-bit grayscale PNG: cam0 images must be 8-bit grayscale");
  EXPECT_EQ(InputErrorOf([] { DecodeGrayPng(Encode(Ramp(CV_8UC3))); }),
            "RGB PNG: cam0 images must be 8-bit grayscale");
  EXPECT_EQ(InputErrorOf([] { DecodeGrayPng(Encode(Ramp(CV_8UC4))); }),
            "RGBA PNG: cam0 images must be 8-bit grayscale");
  // A PGM file named .png.
  std::vector<uchar> pgm;
  ASSERT_TRUE(cv::imencode(".pgm", Ramp(CV_8UC1), pgm));
  EXPECT_NE(InputErrorOf([&] { DecodeGrayPng(std::string(pgm.begin(), pgm.end())); }).find("not a PNG file"),
            std::string::npos);
}

TEST(GrayPng, CorruptFilesGiveLibpngsReasonInOneLine) {
  const std::string good = Encode(Ramp(CV_8UC1));
  const std::string truncated = InputErrorOf([&] { DecodeGrayPng(good.substr(0, good.size() / 2)); });
  EXPECT_EQ(truncated.rfind("corrupt PNG: ", 0), 0u) << truncated;
  std::string corrupt = good;
  const std::size_t idat = corrupt.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  for (std::size_t i = idat + 6; i < idat + 14 && i < corrupt.size(); ++i)
    corrupt[i] = static_cast<char>(0xff);
  const std::string bad_data = InputErrorOf([&] { DecodeGrayPng(corrupt); });
  EXPECT_EQ(bad_data.rfind("corrupt PNG: ", 0), 0u) << bad_data;
  // An IHDR claiming 2^20 x 2^20 pixels (CRC fixed or not, it is refused before any allocation).
  std::string huge = good;
  const std::size_t ihdr = huge.find("IHDR");
  huge[ihdr + 4] = 0, huge[ihdr + 5] = 0x10, huge[ihdr + 6] = 0, huge[ihdr + 7] = 0;
  EXPECT_EQ(InputErrorOf([&] { DecodeGrayPng(huge); }).rfind("corrupt PNG: ", 0), 0u);
  for (const std::string& e : {truncated, bad_data}) EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

}  // namespace
}  // namespace vigil::frontend
