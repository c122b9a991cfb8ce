#include "detectors/slice_features.h"

#include <algorithm>

namespace vigil::detectors {

void ExtractChannels(const ImuSample* samples, int m, int dims, double* out) {
  for (int i = 0; i < m; ++i)
    for (int c = 0; c < dims; ++c) out[i * dims + c] = samples[i].axis(ChannelAxis(c));
}

double MedianInPlace(double* values, int n) {
  const int mid = n / 2;
  std::nth_element(values, values + mid, values + n);
  const double upper = values[mid];
  if (n % 2 == 1) return upper;
  const double lower = *std::max_element(values, values + mid);
  return 0.5 * (lower + upper);
}

void FitBaseline(const double* x, int m, int dims, SliceNormalization normalization, SliceBaseline* baseline,
                 std::vector<double>* scratch) {
  baseline->offset.assign(dims, 0.0);
  baseline->slope.assign(dims, 0.0);
  if (normalization == SliceNormalization::kNone) return;
  scratch->resize(m);
  double* v = scratch->data();
  for (int c = 0; c < dims; ++c) {
    if (normalization == SliceNormalization::kMedian || m < 2) {
      for (int i = 0; i < m; ++i) v[i] = x[i * dims + c];
      baseline->offset[c] = MedianInPlace(v, m);
      continue;
    }
    const int half = m / 2;  // first half [0, half), second half [half, m)
    for (int i = 0; i < m; ++i) v[i] = x[i * dims + c];
    const double median_first = MedianInPlace(v, half);
    const double median_second = MedianInPlace(v + half, m - half);
    const double centre_first = 0.5 * (half - 1), centre_second = 0.5 * (half + m - 1);
    const double slope = (median_second - median_first) / (centre_second - centre_first);
    baseline->slope[c] = slope;
    baseline->offset[c] = median_first + slope * (0.5 * (m - 1) - centre_first);
  }
}

void SubtractBaseline(const SliceBaseline& baseline, int m, int dims, double* x) {
  for (int i = 0; i < m; ++i)
    for (int c = 0; c < dims; ++c) x[i * dims + c] -= baseline.At(c, i, m);
}

void ResampleRows(const double* x, int m, int dims, int n, double* out) {
  const double width = static_cast<double>(m) / n;  // input rows per output row
  for (int j = 0; j < n; ++j) {
    const double lo = j * width, hi = (j + 1) * width;
    for (int c = 0; c < dims; ++c) out[j * dims + c] = 0.0;
    for (int i = static_cast<int>(lo); i < m && i < hi; ++i) {
      const double w = std::min(hi, i + 1.0) - std::max(lo, static_cast<double>(i));
      if (w <= 0.0) continue;
      for (int c = 0; c < dims; ++c) out[j * dims + c] += w * x[i * dims + c];
    }
    for (int c = 0; c < dims; ++c) out[j * dims + c] /= width;
  }
}

}  // namespace vigil::detectors

namespace vigil::detectors {

void NormalizeSlice(const ImuSample* samples, int m, int dims, SliceNormalization normalization, double* out,
                    SliceBaseline* baseline, std::vector<double>* scratch) {
  ExtractChannels(samples, m, dims, out);
  FitBaseline(out, m, dims, normalization, baseline, scratch);
  SubtractBaseline(*baseline, m, dims, out);
}

}  // namespace vigil::detectors
