// Shi-Tomasi corners where a mask is open, at the cost of the open part of the image only.
//
// The corners of cv::goodFeaturesToTrack (minimum-eigenvalue score of the 3 x 3 Sobel gradients summed over a
// 3 x 3 block; a corner is a 3 x 3 local maximum scoring above quality_level x the best score inside the
// mask, not on the image's outermost rows and columns; strongest first, each at least min_distance_px from
// the stronger ones kept), but nothing is computed over the whole image: the gradients, their block sums and
// the score are computed along the row runs of the open mask pixels and of their neighbours only, in one pass
// down the image that keeps three rows of each (so that it works in the cache). The tracker's mask is mostly
// closed (discs around its tracks; about 15 % of a frame stays open), and a full-image score map was most of
// a frame's cost. Scores come from exact integer gradient sums, so they are proportional to OpenCV's float
// scores up to rounding (the same corners but for near-ties). Equal scores are ordered as OpenCV orders them
// (the later pixel in row-major order first): the output is a deterministic function of the image and the
// mask.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace vigil::frontend {

struct CornerDetectorOptions {
  int max_corners = 150;
  double quality_level = 0.01;    // score relative to the best score inside the mask
  double min_distance_px = 30.0;  // between two returned corners
};

// `image` 8-bit, one channel; `mask` of the same size, 8-bit, nonzero where corners may lie.
std::vector<cv::Point2f> DetectShiTomasiCorners(const cv::Mat& image, const cv::Mat& mask,
                                                const CornerDetectorOptions& options);

}  // namespace vigil::frontend
