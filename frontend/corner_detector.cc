#include "frontend/corner_detector.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <opencv2/imgproc.hpp>

namespace vigil::frontend {
namespace {

// cv::goodFeaturesToTrack's defaults: 3 x 3 Sobel gradients summed over a 3 x 3 block (MinEigenScore).
constexpr int kSobelSize = 3;
// Non-maximum suppression over 3 x 3 neighbourhoods.
constexpr int kNmsRadius = 1;

struct Candidate {
  float score;
  int x, y;
};

// BORDER_REFLECT_101 index (OpenCV's default border, as in cv::cornerMinEigenVal).
int Reflect(int i, int n) { return i < 0 ? -i : (i >= n ? 2 * n - 2 - i : i); }

// s[x] = v[x - 1] + v[x] + v[x + 1] over a row of w >= 2 values (BORDER_REFLECT_101 at its ends).
void SumAcross3(const int32_t* v, int w, int32_t* s) {
  s[0] = v[0] + 2 * v[1];
  for (int x = 1; x + 1 < w; ++x) s[x] = v[x - 1] + v[x] + v[x + 1];
  s[w - 1] = v[w - 1] + 2 * v[w - 2];
}

// The rows of `across` summed over 3 rows (BORDER_REFLECT_101 at the first and last).
cv::Mat SumDown3(const cv::Mat& across) {
  cv::Mat out(across.size(), CV_32SC1);
  const int w = across.cols;
  for (int y = 0; y < across.rows; ++y) {
    const int32_t* a = across.ptr<int32_t>(Reflect(y - 1, across.rows));
    const int32_t* b = across.ptr<int32_t>(y);
    const int32_t* c = across.ptr<int32_t>(Reflect(y + 1, across.rows));
    int32_t* o = out.ptr<int32_t>(y);
    for (int x = 0; x < w; ++x) o[x] = a[x] + b[x] + c[x];
  }
  return out;
}

// The gradients' second-moment matrix [xx xy; xy yy] summed over each pixel's 3 x 3 block, from 3 x 3 Sobel
// gradients: exact integers (|gradient| <= 1020, so a block sum stays below 2^24).
struct SecondMoments {
  cv::Mat xx, xy, yy;  // CV_32SC1
};

SecondMoments BlockMoments(const cv::Mat& image) {
  cv::Mat dx, dy;
  cv::Sobel(image, dx, CV_16S, 1, 0, kSobelSize, 1.0, 0.0, cv::BORDER_REFLECT_101);
  cv::Sobel(image, dy, CV_16S, 0, 1, kSobelSize, 1.0, 0.0, cv::BORDER_REFLECT_101);
  const int w = image.cols;
  cv::Mat xx(image.size(), CV_32SC1), xy(image.size(), CV_32SC1), yy(image.size(), CV_32SC1);
  std::vector<int32_t> pxx(static_cast<std::size_t>(w)), pxy(pxx.size()), pyy(pxx.size());
  for (int y = 0; y < image.rows; ++y) {
    const int16_t* gx = dx.ptr<int16_t>(y);
    const int16_t* gy = dy.ptr<int16_t>(y);
    for (int x = 0; x < w; ++x) {
      const int32_t ex = gx[x], ey = gy[x];
      pxx[static_cast<std::size_t>(x)] = ex * ex;
      pxy[static_cast<std::size_t>(x)] = ex * ey;
      pyy[static_cast<std::size_t>(x)] = ey * ey;
    }
    SumAcross3(pxx.data(), w, xx.ptr<int32_t>(y));
    SumAcross3(pxy.data(), w, xy.ptr<int32_t>(y));
    SumAcross3(pyy.data(), w, yy.ptr<int32_t>(y));
  }
  return {SumDown3(xx), SumDown3(xy), SumDown3(yy)};
}

// The smaller eigenvalue of [a b; b c]: the Shi-Tomasi score, proportional to cv::cornerMinEigenVal's (which
// scales the gradients and rounds in float); the ratio to the best score, all that matters here, is the same.
float MinEigenvalue(int32_t a, int32_t b, int32_t c) {
  const double half_trace = 0.5 * (static_cast<double>(a) + c);
  const double half_diff = 0.5 * (static_cast<double>(a) - c);
  return static_cast<float>(half_trace - std::sqrt(half_diff * half_diff + static_cast<double>(b) * b));
}

// Scores at every open mask pixel and its suppression neighbours (zero elsewhere), and the best score on an
// open pixel.
cv::Mat ScoresWhereOpen(const cv::Mat& image, const cv::Mat& mask, double* best_open) {
  const SecondMoments m = BlockMoments(image);
  cv::Mat needed;
  cv::dilate(mask, needed, cv::Mat(), cv::Point(-1, -1), kNmsRadius);
  cv::Mat scores(image.size(), CV_32FC1, cv::Scalar(0));
  float best = 0.0f;
  for (int y = 0; y < image.rows; ++y) {
    const uchar* need = needed.ptr<uchar>(y);
    const uchar* open = mask.ptr<uchar>(y);
    const int32_t* xx = m.xx.ptr<int32_t>(y);
    const int32_t* xy = m.xy.ptr<int32_t>(y);
    const int32_t* yy = m.yy.ptr<int32_t>(y);
    float* row = scores.ptr<float>(y);
    for (int x = 0; x < image.cols; ++x) {
      if (!need[x]) continue;
      row[x] = MinEigenvalue(xx[x], xy[x], yy[x]);
      if (open[x]) best = std::max(best, row[x]);
    }
  }
  *best_open = best;
  return scores;
}

// Local maxima above `threshold` on open mask pixels, not on the image's outermost rows and columns.
std::vector<Candidate> LocalMaxima(const cv::Mat& scores, const cv::Mat& mask, float threshold) {
  std::vector<Candidate> out;
  for (int y = 1; y + 1 < scores.rows; ++y) {
    const float* above = scores.ptr<float>(y - 1);
    const float* row = scores.ptr<float>(y);
    const float* below = scores.ptr<float>(y + 1);
    const uchar* open = mask.ptr<uchar>(y);
    for (int x = 1; x + 1 < scores.cols; ++x) {
      const float s = row[x];
      if (s <= threshold || !open[x]) continue;
      const bool is_max = s >= row[x - 1] && s >= row[x + 1] && s >= above[x - 1] && s >= above[x] &&
                          s >= above[x + 1] && s >= below[x - 1] && s >= below[x] && s >= below[x + 1];
      if (is_max) out.push_back({s, x, y});
    }
  }
  return out;
}

// Strongest first; each kept corner at least min_distance_px from the stronger ones kept (grid lookup).
std::vector<cv::Point2f> SelectSpaced(std::vector<Candidate> candidates, const CornerDetectorOptions& options,
                                      cv::Size size) {
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.score != b.score) return a.score > b.score;
    return a.y != b.y ? a.y > b.y : a.x > b.x;  // as OpenCV: the later pixel first
  });
  std::vector<cv::Point2f> kept;
  const double min_d = options.min_distance_px;
  if (min_d <= 0.0) {
    for (const Candidate& c : candidates) {
      if (static_cast<int>(kept.size()) >= options.max_corners) break;
      kept.emplace_back(static_cast<float>(c.x), static_cast<float>(c.y));
    }
    return kept;
  }
  const int cell = std::max(1, static_cast<int>(std::ceil(min_d)));
  const int grid_w = (size.width + cell - 1) / cell, grid_h = (size.height + cell - 1) / cell;
  std::vector<std::vector<cv::Point2f>> grid(static_cast<std::size_t>(grid_w) * grid_h);
  const double min_d2 = min_d * min_d;
  for (const Candidate& c : candidates) {
    if (static_cast<int>(kept.size()) >= options.max_corners) break;
    const int gx = c.x / cell, gy = c.y / cell;
    bool crowded = false;
    for (int y = std::max(gy - 1, 0); y <= std::min(gy + 1, grid_h - 1) && !crowded; ++y)
      for (int x = std::max(gx - 1, 0); x <= std::min(gx + 1, grid_w - 1) && !crowded; ++x)
        for (const cv::Point2f& p : grid[static_cast<std::size_t>(y) * grid_w + x]) {
          const double dx = p.x - c.x, dy = p.y - c.y;
          if (dx * dx + dy * dy < min_d2) {
            crowded = true;
            break;
          }
        }
    if (crowded) continue;
    const cv::Point2f p(static_cast<float>(c.x), static_cast<float>(c.y));
    grid[static_cast<std::size_t>(gy) * grid_w + gx].push_back(p);
    kept.push_back(p);
  }
  return kept;
}

}  // namespace

std::vector<cv::Point2f> DetectShiTomasiCorners(const cv::Mat& image, const cv::Mat& mask,
                                                const CornerDetectorOptions& options) {
  CV_Assert(image.type() == CV_8UC1 && mask.type() == CV_8UC1 && image.size() == mask.size());
  if (options.max_corners <= 0) return {};
  double best = 0.0;
  const cv::Mat scores = ScoresWhereOpen(image, mask, &best);
  if (best <= 0.0) return {};
  const float threshold = static_cast<float>(best * options.quality_level);
  return SelectSpaced(LocalMaxima(scores, mask, threshold), options, image.size());
}

}  // namespace vigil::frontend
