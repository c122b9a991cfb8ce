// Dynamic time warping distances between multivariate series: the reference implementations.
//
// A series of length L and dimension d is L rows of d values, row-major (row t = values[t * d .. t * d + d)).
// The DTW distance is the paper's Algorithm 1 (Long et al., IFAC 2020): the cell cost is the squared
// Euclidean distance between a template row and a slice row ("dependent" multivariate DTW), there is no
// warping window, no square root and no normalization by the path length; every row of both series is matched
// at least once, the path runs from (0, 0) to (N - 1, M - 1) with steps (1, 0), (0, 1) and (1, 1).
//
// These functions are the scalar double-precision ground truth. The production path (dtw_matcher.h) computes
// the same distances in float with templates in SIMD lanes.
#pragma once

#include <utility>
#include <vector>

namespace vigil::detectors {

// Squared Euclidean distance of two d-dimensional rows.
double SquaredDistance(const double* a, const double* b, int dims);

// Algorithm 1: one rolling row of M + 1 cells, O(N M d) time, O(M) memory. `row` is scratch of at least
// m + 1 doubles (so a caller looping over templates allocates nothing). Returns the distance.
double DtwDistance(const double* templ, int n, const double* slice, int m, int dims, double* row);
// The same with its own scratch.
double DtwDistance(const double* templ, int n, const double* slice, int m, int dims);

// The optimal warping path between a template (n rows) and a slice (m rows), from the full (n x m)
// accumulated-cost matrix. Ties are broken toward the diagonal step, then the template step.
struct DtwAlignment {
  double distance = 0.0;                  // equals DtwDistance()
  std::vector<std::pair<int, int>> path;  // (template row, slice row), from (0, 0) to (n - 1, m - 1)
};
DtwAlignment DtwAlign(const double* templ, int n, const double* slice, int m, int dims);

}  // namespace vigil::detectors
