#include "frontend/corner_detector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <Eigen/Core>
#include <opencv2/imgproc.hpp>

namespace vigil::frontend {
namespace {

// Non-maximum suppression over 3 x 3 neighbourhoods.
constexpr int kNmsRadius = 1;
// Scores are needed at the open pixels and their suppression neighbours, gradient products one pixel farther
// (a score's 3 x 3 block).
constexpr int kScoreReach = kNmsRadius;
constexpr int kProductReach = kNmsRadius + 1;

struct Candidate {
  float score;
  int x, y;
};

// A run of pixels of one image row: [x0, x1).
struct Run {
  int x0, x1;
};

// BORDER_REFLECT_101 index (OpenCV's default border, as in cv::cornerMinEigenVal).
int Reflect(int i, int n) { return i < 0 ? -i : (i >= n ? 2 * n - 2 - i : i); }

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

// The row runs of a mask's nonzero pixels, and those of the mask dilated by a square (cv::dilate's, which
// does not reach across the image border), derived from the mask's own runs.
class MaskRuns {
 public:
  explicit MaskRuns(const cv::Mat& mask) : width_(mask.cols), height_(mask.rows) {
    first_.reserve(static_cast<std::size_t>(height_) + 1);
    for (int y = 0; y < height_; ++y) {
      first_.push_back(runs_.size());
      const uchar* row = mask.ptr<uchar>(y);
      for (int x = FindNext(row, 0, width_, true); x < width_;) {
        const int x1 = FindNext(row, x, width_, false);
        runs_.push_back({x, x1});
        x = FindNext(row, x1, width_, true);
      }
    }
    first_.push_back(runs_.size());
  }

  // Row y's runs of the mask.
  const Run* begin(int y) const { return runs_.data() + first_[static_cast<std::size_t>(y)]; }
  const Run* end(int y) const { return runs_.data() + first_[static_cast<std::size_t>(y) + 1]; }

  // Row y's runs of the mask dilated by the (2 radius + 1)^2 square (radius <= kProductReach): the runs of
  // rows y - radius .. y + radius, each grown by radius and clipped to the image, taken in order of their
  // first pixel (each row's are in order already) and merged where they overlap or touch.
  void Dilated(int y, int radius, std::vector<Run>* out) const {
    CV_DbgAssert(radius <= kProductReach);
    std::array<const Run*, 2 * kProductReach + 1> next{}, last{};
    std::size_t rows = 0;
    for (int r = std::max(y - radius, 0); r <= std::min(y + radius, height_ - 1); ++r, ++rows) {
      next[rows] = begin(r);
      last[rows] = end(r);
    }
    out->clear();
    for (;;) {
      std::size_t pick = rows;
      for (std::size_t k = 0; k < rows; ++k)
        if (next[k] != last[k] && (pick == rows || next[k]->x0 < next[pick]->x0)) pick = k;
      if (pick == rows) return;
      const Run grown{std::max(next[pick]->x0 - radius, 0), std::min(next[pick]->x1 + radius, width_)};
      ++next[pick];
      if (!out->empty() && grown.x0 <= out->back().x1)
        out->back().x1 = std::max(out->back().x1, grown.x1);
      else
        out->push_back(grown);
    }
  }

 private:
  int width_, height_;
  std::vector<Run> runs_;
  std::vector<std::size_t> first_;  // row y's runs are runs_[first_[y], first_[y + 1])
};

// The Sobel gradient products gx^2, gx gy, gy^2 at pixels [x0, x1) of an image row, from the rows above, at
// and below it of an image padded by one pixel (so pixel x of the row is at x + 1 there). (A function of its
// own: the compiler vectorizes the loop when it knows that the outputs alias nothing.)
void GradientProducts(const uchar* __restrict up, const uchar* __restrict mid, const uchar* __restrict down,
                      int x0, int x1, int32_t* __restrict xx, int32_t* __restrict xy,
                      int32_t* __restrict yy) {
  for (int x = x0; x < x1; ++x) {
    const int32_t gx = (up[x + 2] - up[x]) + 2 * (mid[x + 2] - mid[x]) + (down[x + 2] - down[x]);
    const int32_t gy = (down[x] + 2 * down[x + 1] + down[x + 2]) - (up[x] + 2 * up[x + 1] + up[x + 2]);
    xx[x] = gx * gx;
    xy[x] = gx * gy;
    yy[x] = gy * gy;
  }
}

// Shi-Tomasi scores row by row: the smaller eigenvalue of the second-moment matrix [xx xy; xy yy] of the
// 3 x 3 Sobel gradients (cv::Sobel's kernel), summed over each pixel's 3 x 3 block, with BORDER_REFLECT_101
// for the gradients and for the block sums at the image border, as cv::cornerMinEigenVal. The sums are exact
// integers (|gradient| <= 1020, so a block sum stays below 2^24). Only the gradient products and the scores
// of the last three rows are kept (ring buffers of rows), all that the block sums and the 3 x 3 non-maximum
// suppression read: the working set stays in the cache.
class RowScorer {
 public:
  explicit RowScorer(const cv::Mat& image) : width_(image.cols), height_(image.rows) {
    cv::copyMakeBorder(image, padded_, 1, 1, 1, 1, cv::BORDER_REFLECT_101);
    products_.resize(static_cast<std::size_t>(kRing) * kPlanes * static_cast<std::size_t>(width_));
    scores_.resize(static_cast<std::size_t>(kRing) * static_cast<std::size_t>(width_));
    for (std::vector<int32_t>& sums : sums_) sums.resize(static_cast<std::size_t>(width_) + 2);
    for (Eigen::ArrayXd& block : block_) block.resize(width_);
    score_.resize(width_);
  }

  // The gradient products gx^2, gx gy, gy^2 of row y at the run's pixels.
  void Products(int y, const Run& run) {
    // The padded image is shifted by one pixel: its rows y .. y + 2 are the image's rows y - 1 .. y + 1.
    GradientProducts(padded_.ptr<uchar>(y), padded_.ptr<uchar>(y + 1), padded_.ptr<uchar>(y + 2), run.x0,
                     run.x1, Product(0, y), Product(1, y), Product(2, y));
  }

  // The scores of row y at the run's pixels; reads the products of rows y - 1 .. y + 1 within one pixel of
  // the run.
  void Score(int y, const Run& run) {
    // Down: the block's three rows, over the run and one pixel either side (sums_ index = column + 1).
    const int a = Reflect(y - 1, height_), c = Reflect(y + 1, height_);
    const int lo = std::max(run.x0 - 1, 0), hi = std::min(run.x1 + 1, width_);
    for (int k = 0; k < kPlanes; ++k) {
      const int32_t* pa = Product(k, a);
      const int32_t* pb = Product(k, y);
      const int32_t* pc = Product(k, c);
      int32_t* sum = sums_[static_cast<std::size_t>(k)].data() + 1;
      for (int x = lo; x < hi; ++x) sum[x] = pa[x] + pb[x] + pc[x];
      // BORDER_REFLECT_101 at the first and last columns
      if (run.x0 == 0) sum[-1] = sum[1];
      if (run.x1 == width_) sum[width_] = sum[width_ - 2];
    }
    // Across, then the score: half trace - sqrt(half difference^2 + xy^2), in double as one array expression.
    const int n = run.x1 - run.x0;
    for (int k = 0; k < kPlanes; ++k) {
      const int32_t* sum = sums_[static_cast<std::size_t>(k)].data() + 1 + run.x0;
      double* block = block_[static_cast<std::size_t>(k)].data();
      for (int i = 0; i < n; ++i) block[i] = static_cast<double>(sum[i - 1] + sum[i] + sum[i + 1]);
    }
    const auto xx = block_[0].head(n), xy = block_[1].head(n), yy = block_[2].head(n);
    const auto half_diff = 0.5 * (xx - yy);
    // (evaluated in double first: Eigen does not vectorize an expression that changes the scalar type)
    score_.head(n) = 0.5 * (xx + yy) - (half_diff * half_diff + xy * xy).sqrt();
    Eigen::Map<Eigen::ArrayXf>(MutableScoreRow(y) + run.x0, n) = score_.head(n).cast<float>();
  }

  // Row y's scores (set where Score ran for y; the ring keeps rows y - 2 .. y).
  const float* ScoreRow(int y) const { return scores_.data() + Slot(y) * static_cast<std::size_t>(width_); }

 private:
  static constexpr int kRing = 3, kPlanes = 3;

  static std::size_t Slot(int y) { return static_cast<std::size_t>(y % kRing); }
  int32_t* Product(int plane, int y) {
    return products_.data() +
           (Slot(y) * kPlanes + static_cast<std::size_t>(plane)) * static_cast<std::size_t>(width_);
  }
  float* MutableScoreRow(int y) { return scores_.data() + Slot(y) * static_cast<std::size_t>(width_); }

  int width_, height_;
  cv::Mat padded_;                            // the image with a 1-pixel BORDER_REFLECT_101 frame
  std::vector<int32_t> products_;             // [row slot][plane][column]: gx^2, gx gy, gy^2
  std::vector<float> scores_;                 // [row slot][column]
  std::array<std::vector<int32_t>, 3> sums_;  // one row's block sums down, with a column either side
  std::array<Eigen::ArrayXd, 3> block_;       // one run's block sums, as doubles
  Eigen::ArrayXd score_;                      // one run's scores, in double
};

// Row y's local maxima above `threshold` on its open runs, not on the image's outermost columns; y is not an
// outermost row.
void RowMaxima(const float* above, const float* row, const float* below, int y, int width, const Run* begin,
               const Run* end, float threshold, std::vector<Candidate>* out) {
  for (const Run* run = begin; run != end; ++run) {
    for (int x = std::max(run->x0, 1); x < std::min(run->x1, width - 1); ++x) {
      const float s = row[x];
      if (s <= threshold) continue;
      const bool is_max = s >= row[x - 1] && s >= row[x + 1] && s >= above[x - 1] && s >= above[x] &&
                          s >= above[x + 1] && s >= below[x - 1] && s >= below[x] && s >= below[x + 1];
      if (is_max) out->push_back({s, x, y});
    }
  }
}

// The local maxima on open pixels scoring above quality_level x the best score on an open pixel, in one pass
// down the image. The threshold is known only at the end: candidates are kept above the threshold of the best
// score so far (never above the final one) and filtered once more at the end.
std::vector<Candidate> OpenMaxima(const cv::Mat& image, const cv::Mat& mask, double quality_level) {
  const MaskRuns open(mask);
  RowScorer scorer(image);
  const int height = image.rows;
  std::vector<Run> runs;
  std::vector<Candidate> candidates;
  float best_open = 0.0f;
  const auto threshold = [&] { return static_cast<float>(static_cast<double>(best_open) * quality_level); };
  for (int y = 0; y < height; ++y) {
    // Products of the rows the scores of row y read: up to y + 1 (row 0's reflected neighbour is row 1).
    for (int r = y == 0 ? 0 : y + 1; r <= std::min(y + 1, height - 1); ++r) {
      open.Dilated(r, kProductReach, &runs);
      for (const Run& run : runs) scorer.Products(r, run);
    }
    open.Dilated(y, kScoreReach, &runs);
    for (const Run& run : runs) scorer.Score(y, run);
    const float* row = scorer.ScoreRow(y);
    for (const Run* run = open.begin(y); run != open.end(y); ++run)
      best_open =
          std::max(best_open, Eigen::Map<const Eigen::ArrayXf>(row + run->x0, run->x1 - run->x0).maxCoeff());
    // Row y - 1's maxima, now that its neighbours' scores are known.
    const int m = y - 1;
    if (m >= 1)
      RowMaxima(scorer.ScoreRow(m - 1), scorer.ScoreRow(m), row, m, image.cols, open.begin(m), open.end(m),
                threshold(), &candidates);
  }
  if (best_open <= 0.0f) return {};
  const float final_threshold = threshold();
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [&](const Candidate& c) { return c.score <= final_threshold; }),
                   candidates.end());
  return candidates;
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
  return SelectSpaced(OpenMaxima(image, mask, options.quality_level), options, image.size());
}

}  // namespace vigil::frontend
