#include "frontend/corner_detector.h"

#include <algorithm>
#include <iterator>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "tests/frontend/synthetic_images.h"

namespace vigil::frontend {
namespace {

using testing::MakeTexture;

std::vector<std::tuple<float, float>> Sorted(const std::vector<cv::Point2f>& points) {
  std::vector<std::tuple<float, float>> out;
  for (const cv::Point2f& p : points) out.emplace_back(p.x, p.y);
  std::sort(out.begin(), out.end());
  return out;
}

// A mask as the tracker draws it: open, with closed discs around existing tracks.
cv::Mat DiscMask(cv::Size size, int discs, int radius, uint64_t seed) {
  cv::Mat mask(size, CV_8UC1, cv::Scalar(255));
  Rng rng(seed, "mask");
  for (int i = 0; i < discs; ++i)
    cv::circle(mask,
               cv::Point(static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(size.width))),
                         static_cast<int>(rng.UniformIndex(static_cast<uint64_t>(size.height)))),
               radius, cv::Scalar(0), cv::FILLED);
  return mask;
}

// Shared corners of two sets (exact pixel positions).
std::size_t Common(const std::vector<cv::Point2f>& a, const std::vector<cv::Point2f>& b) {
  const auto sa = Sorted(a), sb = Sorted(b);
  std::vector<std::tuple<float, float>> both;
  std::set_intersection(sa.begin(), sa.end(), sb.begin(), sb.end(), std::back_inserter(both));
  return both.size();
}

// The corners are OpenCV's: cv::goodFeaturesToTrack's for the same image and mask, but for the rare near-tie
// that float rounding orders differently (the score here is computed on the open part of the image only).
TEST(CornerDetector, FindsGoodFeaturesToTracksCorners) {
  for (const uint64_t seed : {31u, 33u}) {
    const cv::Mat image = MakeTexture(640, 480, seed);
    for (const int discs : {0, 60, 140}) {
      const cv::Mat mask = DiscMask(image.size(), discs, 30, seed);
      std::vector<cv::Point2f> expected;
      cv::goodFeaturesToTrack(image, expected, 150, 0.01, 30.0, mask);
      const std::vector<cv::Point2f> corners = DetectShiTomasiCorners(image, mask, CornerDetectorOptions{});
      ASSERT_GT(expected.size(), discs == 140 ? 5u : 50u) << discs << " discs";
      EXPECT_EQ(corners.size(), expected.size()) << discs << " discs";
      EXPECT_GE(static_cast<double>(Common(corners, expected)), 0.95 * static_cast<double>(expected.size()))
          << discs << " discs, seed " << seed;
    }
  }
}

TEST(CornerDetector, RespectsMaskSpacingAndCount) {
  const cv::Mat image = MakeTexture(640, 480, 32);
  const cv::Mat mask = DiscMask(image.size(), 80, 30, 9);
  CornerDetectorOptions options;
  options.max_corners = 40;
  options.min_distance_px = 20.0;
  const std::vector<cv::Point2f> corners = DetectShiTomasiCorners(image, mask, options);
  ASSERT_EQ(corners.size(), 40u);
  for (std::size_t i = 0; i < corners.size(); ++i) {
    EXPECT_NE(mask.at<uchar>(cv::Point(corners[i])), 0) << "corner in a closed part of the mask";
    for (std::size_t j = 0; j < i; ++j) EXPECT_GE(cv::norm(corners[i] - corners[j]), 20.0);
  }
  // A closed mask gives nothing, a flat image gives nothing.
  EXPECT_TRUE(DetectShiTomasiCorners(image, cv::Mat::zeros(image.size(), CV_8UC1), options).empty());
  EXPECT_TRUE(DetectShiTomasiCorners(cv::Mat(image.size(), CV_8UC1, cv::Scalar(90)), mask, options).empty());
}

}  // namespace
}  // namespace vigil::frontend
