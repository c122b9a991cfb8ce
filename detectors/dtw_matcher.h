// Production DTW: the distances of one slice to every template of a set, fast and allocation-free.
//
// Same distance as DtwDistance() (Algorithm 1: squared Euclidean cell cost, no window, no square root),
// computed in float with the templates in SIMD lanes: template t sits in lane t % 8 of lane group t / 8
// (structure of arrays), so one vector instruction advances one DTW cell of eight templates at once, and two
// lane groups are interleaved so that the min/add dependency chains of the recurrence overlap. The kernel is
// compiled twice, for AVX2 + FMA and for the baseline instruction set, and chosen at run time
// (__builtin_cpu_supports), so the default build needs no -march flag.
//
// There is no early abandoning: all templates of a lane group advance together, so dropping one lane saves no
// instruction, and with the paper's k = 10 both groups run interleaved to the end (their chains overlap,
// which is what makes the kernel fast). Measured with bench_detectors: about 3 us per slice for k = 10, N =
// 40, M = 40, d = 3 (0.18 ns per cell, ~20x the scalar double reference), close to the vector units'
// throughput.
//
// A matcher owns its scratch row; after construction (and once the largest slice length has been seen)
// Distances() and Best() allocate nothing. A matcher is not thread-safe: use one per thread.
#pragma once

#include <limits>
#include <vector>

namespace vigil::detectors {

namespace internal {
// One lane group: eight floats, aligned for a 256-bit load.
struct alignas(32) Lane8 {
  float v[8];
};
}  // namespace internal

struct DtwMatch {
  int index = -1;  // best template
  double distance = std::numeric_limits<double>::infinity();
};

class DtwMatcher {
 public:
  // `templates`: `count` series of `length` rows x `dims` values, row-major, one after another.
  // 1 <= dims <= 6 (std::invalid_argument otherwise).
  DtwMatcher(const double* templates, int count, int length, int dims);

  int count() const { return count_; }
  int length() const { return length_; }
  int dims() const { return dims_; }

  // DTW distance of `slice` (m rows x dims floats, row-major) to every template: out[0 .. count).
  void Distances(const float* slice, int m, float* out);
  // The best (smallest-distance) template; ties go to the lower index.
  DtwMatch Best(const float* slice, int m);

  // Name of the kernel selected for this CPU: "avx2" or "generic".
  static const char* KernelName();

 private:
  int count_, length_, dims_, groups_;
  std::vector<internal::Lane8> packed_;   // [group][row][dim] lanes
  std::vector<internal::Lane8> scratch_;  // DP row: (m + 1) x 2 lane groups
  std::vector<internal::Lane8> lanes_;    // distances: one Lane8 per group

  void Compute(const float* slice, int m);
};

}  // namespace vigil::detectors
