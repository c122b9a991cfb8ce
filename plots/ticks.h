// Axis ticks at "nice" numbers (1, 2, 2.5 or 5 times a power of ten) and their labels.
#pragma once

#include <string>
#include <vector>

namespace vigil::plots {

struct Ticks {
  double step = 0.0;
  std::vector<double> values;  // multiples of step inside [lo, hi], ascending
};

// At most about `target_count` + 1 ticks covering [lo, hi] (lo < hi, both finite).
Ticks NiceTicks(double lo, double hi, int target_count);

// A tick label with as many decimals as `step` needs ("0.25", "-3", "1e+04" for very large or small
// magnitudes). Never prints "-0".
std::string FormatTick(double value, double step);

// Widens [*lo, *hi] so that it is a valid, non-empty range: equal ends are spread by +-1 (or +-10 % of their
// magnitude), then `pad_fraction` of the span is added on each side.
void PadRange(double* lo, double* hi, double pad_fraction);

}  // namespace vigil::plots
