#include "detectors/dtw_distance.h"

#include <algorithm>
#include <limits>

namespace vigil::detectors {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

double SquaredDistance(const double* a, const double* b, int dims) {
  double sum = 0.0;
  for (int c = 0; c < dims; ++c) {
    const double diff = a[c] - b[c];
    sum += diff * diff;
  }
  return sum;
}

double DtwDistance(const double* templ, int n, const double* slice, int m, int dims, double* row) {
  // row[i] holds the accumulated cost of slice row i - 1 at the current template row; row[0] is the virtual
  // start column (0 before the first template row, infinite afterwards).
  row[0] = 0.0;
  std::fill(row + 1, row + m + 1, kInf);
  for (int level = 0; level < n; ++level) {
    const double* p = templ + static_cast<std::ptrdiff_t>(level) * dims;
    double up_left = row[0];
    row[0] = kInf;
    for (int i = 1; i <= m; ++i) {
      const double cost = SquaredDistance(p, slice + static_cast<std::ptrdiff_t>(i - 1) * dims, dims);
      const double v = cost + std::min({up_left, row[i - 1], row[i]});
      up_left = row[i];
      row[i] = v;
    }
  }
  return row[m];
}

double DtwDistance(const double* templ, int n, const double* slice, int m, int dims) {
  std::vector<double> row(static_cast<std::size_t>(m) + 1);
  return DtwDistance(templ, n, slice, m, dims, row.data());
}

DtwAlignment DtwAlign(const double* templ, int n, const double* slice, int m, int dims) {
  // D(j, i): cost of the best path from (0, 0) to (j, i).
  std::vector<double> acc(static_cast<std::size_t>(n) * m);
  auto at = [&](int j, int i) -> double& { return acc[static_cast<std::size_t>(j) * m + i]; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < m; ++i) {
      const double cost = SquaredDistance(templ + static_cast<std::ptrdiff_t>(j) * dims,
                                          slice + static_cast<std::ptrdiff_t>(i) * dims, dims);
      double best = (j == 0 && i == 0) ? 0.0 : kInf;
      if (j > 0 && i > 0) best = std::min(best, at(j - 1, i - 1));
      if (j > 0) best = std::min(best, at(j - 1, i));
      if (i > 0) best = std::min(best, at(j, i - 1));
      at(j, i) = cost + best;
    }
  }
  DtwAlignment out;
  out.distance = at(n - 1, m - 1);
  int j = n - 1, i = m - 1;
  out.path.emplace_back(j, i);
  while (j > 0 || i > 0) {
    if (j == 0) {
      --i;
    } else if (i == 0) {
      --j;
    } else {
      const double diag = at(j - 1, i - 1), up = at(j - 1, i), left = at(j, i - 1);
      if (diag <= up && diag <= left) {
        --j, --i;
      } else if (up <= left) {
        --j;
      } else {
        --i;
      }
    }
    out.path.emplace_back(j, i);
  }
  std::reverse(out.path.begin(), out.path.end());
  return out;
}

}  // namespace vigil::detectors
