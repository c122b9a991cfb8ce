#include "plots/ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vigil::plots {

Ticks NiceTicks(double lo, double hi, int target_count) {
  Ticks ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double raw = (hi - lo) / std::max(target_count, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    ticks.step = m * magnitude;
    if (ticks.step >= raw * (1.0 - 1e-9)) break;
  }
  // Ticks are computed as integer multiples of the step (no accumulated rounding).
  const double tolerance = ticks.step * 1e-9;
  const auto first = static_cast<long long>(std::ceil((lo - tolerance) / ticks.step));
  const auto last = static_cast<long long>(std::floor((hi + tolerance) / ticks.step));
  for (long long k = first; k <= last; ++k) ticks.values.push_back(static_cast<double>(k) * ticks.step);
  return ticks;
}

std::string FormatTick(double value, double step) {
  if (std::abs(value) < step * 1e-6) value = 0.0;
  char buffer[64];
  const double largest = std::max(std::abs(value), step);
  if (largest >= 1e6 || (step < 1e-4 && value != 0.0)) {
    std::snprintf(buffer, sizeof buffer, "%.3g", value);
  } else {
    int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    // Steps like 0.25 or 2.5 need one digit more than their power of ten.
    const double scaled = step * std::pow(10.0, decimals);
    if (std::abs(scaled - std::round(scaled)) > 1e-6) ++decimals;
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  }
  std::string text = buffer;
  if (text.find_first_not_of("-0.") == std::string::npos && text[0] == '-') text.erase(0, 1);
  return text;
}

void PadRange(double* lo, double* hi, double pad_fraction) {
  if (!std::isfinite(*lo) || !std::isfinite(*hi) || *lo > *hi) {
    *lo = 0.0;
    *hi = 1.0;
  }
  if (*hi - *lo <= 1e-12 * std::max(1.0, std::abs(*lo))) {
    const double spread = *lo == 0.0 ? 1.0 : 0.1 * std::abs(*lo);
    *lo -= spread;
    *hi += spread;
  }
  const double pad = (*hi - *lo) * pad_fraction;
  *lo -= pad;
  *hi += pad;
}

}  // namespace vigil::plots
