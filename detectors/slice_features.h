// The channels a DTW slice compares, and how slices are normalized and shortened into templates.
//
// Channels: d = 3 compares the accelerometer (ax, ay, az [m/s^2]); d = 6 the accelerometer then the gyro
// (ax, ay, az, wx, wy, wz [rad/s]). A slice is m rows x d channels, row-major, in those units.
//
// Normalization removes, per channel, a baseline that carries the slow motion, so that DTW compares the
// short-term shape (where glitches live) and not where the robot happens to be on its trajectory:
//   none    baseline 0 (the paper's raw comparison);
//   median  baseline = the channel's median over the slice;
//   linear  baseline = the line through (centre of first half, median of first half) and (centre of second
//           half, median of second half). Medians make the baseline robust: a glitch in the slice does not
//           move it, so the glitch stays in the normalized slice and the baseline can be kept when the slice
//           is replaced (the replacement keeps the slice's low-frequency content).
#pragma once

#include <vector>

#include "core/types.h"
#include "detectors/detector_options.h"

namespace vigil::detectors {

// IMU axis (imu.csv column order, 0 = wx ... 5 = az) of DTW channel c.
inline int ChannelAxis(int channel) { return channel < 3 ? 3 + channel : channel - 3; }

// Copies the d channels of samples[0 .. m) into out (m x d).
void ExtractChannels(const ImuSample* samples, int m, int dims, double* out);

// Per-channel baseline value(i) = offset[c] + slope[c] * (i - (m - 1) / 2).
struct SliceBaseline {
  std::vector<double> offset, slope;
  double At(int channel, int i, int m) const {
    return offset[channel] + slope[channel] * (i - 0.5 * (m - 1));
  }
};

// Fits the baseline of `x` (m x d). `scratch` avoids allocations on repeated calls.
void FitBaseline(const double* x, int m, int dims, SliceNormalization normalization, SliceBaseline* baseline,
                 std::vector<double>* scratch);
// x(i, c) -= baseline(c, i), in place.
void SubtractBaseline(const SliceBaseline& baseline, int m, int dims, double* x);

// Shortens (or lengthens) m rows to n rows by area averaging: output row j is the mean of the input over the
// time interval [j m / n, (j + 1) m / n) (input row i covering [i, i + 1)). n = m copies.
void ResampleRows(const double* x, int m, int dims, int n, double* out);

// Median of values[0 .. n) (mean of the two middle values for even n); reorders `values`.
double MedianInPlace(double* values, int n);

}  // namespace vigil::detectors

namespace vigil::detectors {

// Extracts the d channels of samples[0 .. m), fits the baseline and subtracts it: out (m x d) is the slice as
// DTW compares it. `baseline` receives what was subtracted.
void NormalizeSlice(const ImuSample* samples, int m, int dims, SliceNormalization normalization, double* out,
                    SliceBaseline* baseline, std::vector<double>* scratch);

}  // namespace vigil::detectors
