#include "frontend/corner_detector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <opencv2/imgproc.hpp>

namespace vigil::frontend {
namespace {

// Non-maximum suppression over 3 x 3 neighbourhoods.
constexpr int kNmsRadius = 1;

struct Candidate {
  float score;
  int x, y;
};

// A run of pixels of one image row: [x0, x1).
struct Run {
  int y, x0, x1;
};

// BORDER_REFLECT_101 index (OpenCV's default border, as in cv::cornerMinEigenVal).
int Reflect(int i, int n) { return i < 0 ? -i : (i >= n ? 2 * n - 2 - i : i); }

// The smaller eigenvalue of [a b; b c]: the Shi-Tomasi score, proportional to cv::cornerMinEigenVal's (which
// scales the gradients and rounds in float); the ratio to the best score, all that matters here, is the same.
float MinEigenvalue(int32_t a, int32_t b, int32_t c) {
  const double half_trace = 0.5 * (static_cast<double>(a) + c);
  const double half_diff = 0.5 * (static_cast<double>(a) - c);
  return static_cast<float>(half_trace - std::sqrt(half_diff * half_diff + static_cast<double>(b) * b));
}

// Index of the first pixel of row[x, end) that is nonzero (`nonzero`) or zero (else); `end` if none. Eight
// pixels at a time where it can: the tracker's masks are long runs.
int FindNext(const uchar* row, int x, int end, bool nonzero) {
  constexpr uint64_t kLow = 0x0101010101010101ULL, kHigh = 0x8080808080808080ULL;
  for (; x + 8 <= end; x += 8) {
    uint64_t word;
    std::memcpy(&word, row + x, sizeof(word));
    const bool has_zero = ((word - kLow) & ~word & kHigh) != 0;
    if (nonzero ? word != 0 : has_zero) break;
  }
  while (x < end && (row[x] != 0) != nonzero) ++x;
  return x;
}

// The row runs of nonzero pixels of `mask`, row by row.
std::vector<Run> NonzeroRuns(const cv::Mat& mask) {
  std::vector<Run> runs;
  for (int y = 0; y < mask.rows; ++y) {
    const uchar* row = mask.ptr<uchar>(y);
    for (int x = FindNext(row, 0, mask.cols, true); x < mask.cols;) {
      const int x1 = FindNext(row, x, mask.cols, false);
      runs.push_back({y, x, x1});
      x = FindNext(row, x1, mask.cols, true);
    }
  }
  return runs;
}

// Shi-Tomasi scores along row runs: the smaller eigenvalue of the second-moment matrix [xx xy; xy yy] of the
// 3 x 3 Sobel gradients (cv::Sobel's kernel), summed over each pixel's 3 x 3 block, with BORDER_REFLECT_101 for
// the gradients and for the block sums at the image border, as cv::cornerMinEigenVal. The sums are exact
// integers (|gradient| <= 1020, so a block sum stays below 2^24).
class RunScorer {
 public:
  explicit RunScorer(const cv::Mat& image) : width_(image.cols), height_(image.rows) {
    cv::copyMakeBorder(image, padded_, 1, 1, 1, 1, cv::BORDER_REFLECT_101);
    for (cv::Mat& plane : products_) plane.create(image.size(), CV_32SC1);
    for (std::vector<int32_t>& sums : sums_) sums.resize(static_cast<std::size_t>(width_) + 2);
  }

  // The gradient products gx^2, gx gy, gy^2 at the run's pixels. Score reads those of the pixels within one
  // pixel of its run (the block).
  void Products(const Run& run) {
    // The padded image is shifted by one pixel: its rows y, y + 1, y + 2 are the image's rows y - 1, y, y + 1.
    const uchar* up = padded_.ptr<uchar>(run.y);
    const uchar* mid = padded_.ptr<uchar>(run.y + 1);
    const uchar* down = padded_.ptr<uchar>(run.y + 2);
    int32_t* xx = products_[0].ptr<int32_t>(run.y);
    int32_t* xy = products_[1].ptr<int32_t>(run.y);
    int32_t* yy = products_[2].ptr<int32_t>(run.y);
    const int x0 = run.x0, x1 = run.x1;  // (locals: the stores below could alias the run)
    for (int x = x0; x < x1; ++x) {
      const int32_t gx = (up[x + 2] - up[x]) + 2 * (mid[x + 2] - mid[x]) + (down[x + 2] - down[x]);
      const int32_t gy = (down[x] + 2 * down[x + 1] + down[x + 2]) - (up[x] + 2 * up[x + 1] + up[x + 2]);
      xx[x] = gx * gx;
      xy[x] = gx * gy;
      yy[x] = gy * gy;
    }
  }

  // The scores of the run's pixels, into `scores` (the image's size, CV_32FC1).
  void Score(const Run& run, cv::Mat* scores) {
    // Down: the block's three rows, over the run and one pixel either side (sums_ index = column + 1).
    const int a = Reflect(run.y - 1, height_), c = Reflect(run.y + 1, height_);
    const int lo = std::max(run.x0 - 1, 0), hi = std::min(run.x1 + 1, width_);
    for (std::size_t k = 0; k < products_.size(); ++k) {
      const int32_t* pa = products_[k].ptr<int32_t>(a);
      const int32_t* pb = products_[k].ptr<int32_t>(run.y);
      const int32_t* pc = products_[k].ptr<int32_t>(c);
      int32_t* sum = sums_[k].data() + 1;
      for (int x = lo; x < hi; ++x) sum[x] = pa[x] + pb[x] + pc[x];
      // BORDER_REFLECT_101 at the first and last columns
      if (run.x0 == 0) sum[-1] = sum[1];
      if (run.x1 == width_) sum[width_] = sum[width_ - 2];
    }
    // Across, then the score.
    const int32_t* xx = sums_[0].data() + 1;
    const int32_t* xy = sums_[1].data() + 1;
    const int32_t* yy = sums_[2].data() + 1;
    float* out = scores->ptr<float>(run.y);
    const int x0 = run.x0, x1 = run.x1;
    for (int x = x0; x < x1; ++x)
      out[x] = MinEigenvalue(xx[x - 1] + xx[x] + xx[x + 1], xy[x - 1] + xy[x] + xy[x + 1],
                             yy[x - 1] + yy[x] + yy[x + 1]);
  }

 private:
  int width_, height_;
  cv::Mat padded_;                       // the image with a 1-pixel BORDER_REFLECT_101 frame
  std::array<cv::Mat, 3> products_;      // gx^2, gx gy, gy^2 (CV_32SC1), set where Products ran
  std::array<std::vector<int32_t>, 3> sums_;  // one row's block sums down, with a column either side
};

// Scores at the open mask pixels and their suppression neighbours (the only ones the detection reads; the
// others are left unset), the runs of open pixels, and the best score on an open pixel.
struct OpenScores {
  cv::Mat scores;  // CV_32FC1
  std::vector<Run> open_runs;
  float best_open = 0.0f;
};

OpenScores ScoresWhereOpen(const cv::Mat& image, const cv::Mat& mask) {
  OpenScores out;
  out.scores.create(image.size(), CV_32FC1);
  // Scores are needed at open pixels and their suppression neighbours, gradient products within one more pixel
  // (a score's block).
  cv::Mat needed, reach;
  cv::dilate(mask, needed, cv::Mat(), cv::Point(-1, -1), kNmsRadius);
  cv::dilate(needed, reach, cv::Mat());
  RunScorer scorer(image);
  for (const Run& run : NonzeroRuns(reach)) scorer.Products(run);
  for (const Run& run : NonzeroRuns(needed)) scorer.Score(run, &out.scores);
  out.open_runs = NonzeroRuns(mask);
  for (const Run& run : out.open_runs) {
    const float* row = out.scores.ptr<float>(run.y);
    for (int x = run.x0; x < run.x1; ++x) out.best_open = std::max(out.best_open, row[x]);
  }
  return out;
}

// Local maxima above `threshold` on the open runs, not on the image's outermost rows and columns.
std::vector<Candidate> LocalMaxima(const cv::Mat& scores, const std::vector<Run>& open_runs, float threshold) {
  std::vector<Candidate> out;
  for (const Run& run : open_runs) {
    if (run.y < 1 || run.y + 1 >= scores.rows) continue;
    const float* above = scores.ptr<float>(run.y - 1);
    const float* row = scores.ptr<float>(run.y);
    const float* below = scores.ptr<float>(run.y + 1);
    for (int x = std::max(run.x0, 1); x < std::min(run.x1, scores.cols - 1); ++x) {
      const float s = row[x];
      if (s <= threshold) continue;
      const bool is_max = s >= row[x - 1] && s >= row[x + 1] && s >= above[x - 1] && s >= above[x] &&
                          s >= above[x + 1] && s >= below[x - 1] && s >= below[x] && s >= below[x + 1];
      if (is_max) out.push_back({s, x, run.y});
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
  // (a corner lies off the outermost rows and columns: an image under 3 x 3 pixels has none)
  if (options.max_corners <= 0 || image.cols < 3 || image.rows < 3) return {};
  const OpenScores open = ScoresWhereOpen(image, mask);
  if (open.best_open <= 0.0f) return {};
  const float threshold = static_cast<float>(static_cast<double>(open.best_open) * options.quality_level);
  return SelectSpaced(LocalMaxima(open.scores, open.open_runs, threshold), options, image.size());
}

}  // namespace vigil::frontend
