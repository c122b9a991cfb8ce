// Mitigation of bad IMU data inside the estimator (section estimator.mitigation), combinable with any
// detector (which replaces or keeps the samples it flags before the estimator sees them):
//   inflate     a sample a detector flagged enters preintegration with its white-noise variance multiplied by
//               variance_factor ("give the IMU a bigger variance"), whether or not the detector replaced it;
//   saturation  a sample with an axis at the sensor's full-scale range is known to be clipped: the same
//               inflation (PX4's EKF2 does this for clipped accelerometer samples);
//   gating      after each window solve, a chi-square test of every IMU factor's whitened residual (15 dof,
//               the configured quantile); a failing factor's covariance is inflated and the window is solved
//               once more.
// All off by default: the estimator then runs exactly as without this section.
#pragma once

#include "core/config.h"

namespace vigil::estimator {

struct InflateOptions {
  bool enabled = false;
  double variance_factor = 1e4;  // sigma x 100: a flagged sample weighs as 1/10^4 of a normal one

  template <class V>
  void Visit(V& v) {
    v.Field("enabled", enabled, "inflate the noise of the samples the detector flagged");
    v.Field("variance_factor", variance_factor,
            "white-noise variance multiplier of a flagged sample in preintegration",
            config::Bounds::AtLeast(1.0));
  }
};

struct SaturationAwareOptions {
  bool enabled = false;
  double accel_range_mps2 = 0.0;     // the sensor's full-scale range (datasheet); 0: not known
  double gyro_range_dps = 0.0;       // [deg/s]; 0: not known
  double tolerance_fraction = 1e-3;  // |x| >= range (1 - tolerance) counts as clipped (quantized readings)
  double variance_factor = 1e4;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("enabled", enabled, "inflate the noise of samples at the sensor's full-scale range (clipped)");
    v.Field("accel_range_mps2", accel_range_mps2,
            "accelerometer full-scale range per axis [m/s^2] (0: no accelerometer clipping known)",
            Bounds::NonNegative());
    v.Field("gyro_range_dps", gyro_range_dps, "gyro full-scale range per axis [deg/s] (0: not known)",
            Bounds::NonNegative());
    v.Field("tolerance_fraction", tolerance_fraction,
            "a reading within this fraction of the range from it counts as clipped",
            Bounds::Closed(0.0, 0.5));
    v.Field("variance_factor", variance_factor, "white-noise variance multiplier of a clipped sample",
            Bounds::AtLeast(1.0));
  }
};

struct GatingOptions {
  bool enabled = false;
  double quantile = 0.999;  // of the chi-square distribution with 15 degrees of freedom
  double variance_factor =
      0.0;  // covariance inflation of a failing factor; 0: to the gate (chi2 / threshold)

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field(
        "enabled", enabled,
        "chi-square test of each IMU factor after a solve; failing factors are inflated and re-solved once");
    v.Field("quantile", quantile,
            "quantile of chi-square(15) that a factor's squared whitened residual may reach",
            Bounds::Closed(0.5, 0.999999));
    v.Field("variance_factor", variance_factor,
            "covariance multiplier of a failing factor (0: chi2 / threshold, which puts it on the gate)",
            Bounds::NonNegative());
  }
};

struct MitigationOptions {
  InflateOptions inflate;
  SaturationAwareOptions saturation;
  GatingOptions gating;

  template <class V>
  void Visit(V& v) {
    v.Section("inflate", inflate, "noise inflation of detector-flagged samples");
    v.Section("saturation", saturation, "noise inflation of clipped samples");
    v.Section("gating", gating, "chi-square gating of IMU factors");
  }
};

}  // namespace vigil::estimator
