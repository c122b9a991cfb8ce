#include "frontend/corner_detector.h"

#include <algorithm>
#include <cmath>
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

// The detector's definition computed the plain way, over the whole image: cv::Sobel gradients, their products
// summed over 3 x 3 blocks by cv::boxFilter (BORDER_REFLECT_101, exact in double), the smaller eigenvalue;
// 3 x 3 local maxima on open pixels off the outermost rows and columns; strongest first (ties: the later
// pixel), each min_distance_px from the stronger ones kept, by brute force.
std::vector<cv::Point2f> PlainShiTomasi(const cv::Mat& image, const cv::Mat& mask,
                                        const CornerDetectorOptions& options) {
  cv::Mat dx, dy;
  cv::Sobel(image, dx, CV_64F, 1, 0, 3, 1.0, 0.0, cv::BORDER_REFLECT_101);
  cv::Sobel(image, dy, CV_64F, 0, 1, 3, 1.0, 0.0, cv::BORDER_REFLECT_101);
  cv::Mat xx, xy, yy;
  cv::boxFilter(dx.mul(dx), xx, CV_64F, cv::Size(3, 3), cv::Point(-1, -1), false, cv::BORDER_REFLECT_101);
  cv::boxFilter(dx.mul(dy), xy, CV_64F, cv::Size(3, 3), cv::Point(-1, -1), false, cv::BORDER_REFLECT_101);
  cv::boxFilter(dy.mul(dy), yy, CV_64F, cv::Size(3, 3), cv::Point(-1, -1), false, cv::BORDER_REFLECT_101);
  cv::Mat score(image.size(), CV_32FC1);
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) {
      const double a = xx.at<double>(y, x), b = xy.at<double>(y, x), c = yy.at<double>(y, x);
      score.at<float>(y, x) = static_cast<float>(0.5 * (a + c) - std::sqrt(0.25 * (a - c) * (a - c) + b * b));
    }
  double best = 0.0;
  cv::minMaxLoc(score, nullptr, &best, nullptr, nullptr, mask);
  if (best <= 0.0) return {};
  const float threshold = static_cast<float>(best * options.quality_level);
  struct Corner {
    float score;
    int x, y;
  };
  std::vector<Corner> corners;
  for (int y = 1; y + 1 < image.rows; ++y)
    for (int x = 1; x + 1 < image.cols; ++x) {
      const float s = score.at<float>(y, x);
      bool is_max = mask.at<uchar>(y, x) != 0 && s > threshold;
      for (int v = -1; v <= 1 && is_max; ++v)
        for (int u = -1; u <= 1; ++u) is_max = is_max && s >= score.at<float>(y + v, x + u);
      if (is_max) corners.push_back({s, x, y});
    }
  std::sort(corners.begin(), corners.end(), [](const Corner& a, const Corner& b) {
    return std::tie(b.score, b.y, b.x) < std::tie(a.score, a.y, a.x);
  });
  std::vector<cv::Point2f> kept;
  for (const Corner& c : corners) {
    if (static_cast<int>(kept.size()) >= options.max_corners) break;
    const cv::Point2f p(static_cast<float>(c.x), static_cast<float>(c.y));
    if (std::all_of(kept.begin(), kept.end(),
                    [&](const cv::Point2f& k) { return cv::norm(k - p) >= options.min_distance_px; }))
      kept.push_back(p);
  }
  return kept;
}

// The score is computed only along the mask's open runs, from exact integer sums: the corners are exactly
// the definition's, in the same order, whatever the mask's shape, wherever it meets the image border, and for
// image sides that are not multiples of anything.
TEST(CornerDetector, MatchesItsDefinitionExactly) {
  const std::vector<cv::Size> sizes = {{640, 480}, {97, 33}, {3, 3}, {5, 200}};
  for (const cv::Size size : sizes) {
    // A texture, and pixel noise: its dense maxima make the border pixels' scores matter.
    cv::Mat noise(size, CV_8UC1);
    cv::RNG rng(41);
    rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
    const std::vector<cv::Mat> images = {MakeTexture(size.width, size.height, 40), noise};
    // Masks: open; discs; open only at single pixels (the four image corners, an edge and the middle).
    cv::Mat dots = cv::Mat::zeros(size, CV_8UC1);
    for (const cv::Point p : {cv::Point(0, 0), cv::Point(size.width - 1, 0), cv::Point(0, size.height - 1),
                              cv::Point(size.width - 1, size.height - 1), cv::Point(1, size.height / 2),
                              cv::Point(size.width / 2, size.height / 2)})
      dots.at<uchar>(p) = 1;  // (any nonzero value opens a pixel)
    const std::vector<cv::Mat> masks = {cv::Mat(size, CV_8UC1, cv::Scalar(255)), DiscMask(size, 60, 30, 1),
                                        DiscMask(size, 140, 30, 2), dots};
    for (std::size_t i = 0; i < images.size(); ++i)
      for (std::size_t m = 0; m < masks.size(); ++m)
        for (const double min_distance_px : {0.0, 10.0, 30.0}) {
          CornerDetectorOptions options;
          options.min_distance_px = min_distance_px;
          EXPECT_EQ(DetectShiTomasiCorners(images[i], masks[m], options),
                    PlainShiTomasi(images[i], masks[m], options))
              << size << ", image " << i << ", mask " << m << ", min distance " << min_distance_px;
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
