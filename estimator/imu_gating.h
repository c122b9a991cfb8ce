// Chi-square gating of IMU factors after a window solve (mitigation_options.h: GatingOptions).
//
// An IMU factor's whitened residual r is 15-dimensional; for a factor consistent with its noise model
// |r|^2 follows chi-square(15). After a solve, a factor with |r|^2 above the configured quantile fails: its
// covariance is inflated (by variance_factor, or by |r|^2 / threshold, which puts the factor exactly on the
// gate, the behaviour of a Huber loss at that point) and the caller solves the window once more. A glitch
// integrated into one factor then pulls the window far less; a factor that fails is only down-weighted,
// never removed, so the window stays connected.
#pragma once

#include <array>
#include <vector>

#include "estimator/imu_factor.h"
#include "estimator/mitigation_options.h"

namespace vigil::estimator {

// The p-quantile of the chi-square distribution with `dof` degrees of freedom (bisection on the regularized
// lower incomplete gamma function; |error| < 1e-9 relative).
double ChiSquareQuantile(int dof, double p);

// An IMU factor with the parameter blocks it was added to the problem with.
struct ImuTerm {
  ImuFactor* factor = nullptr;
  std::array<double*, 4> blocks = {};
};

// What gating did over a run.
struct GatingStats {
  int tests = 0;     // factor tests
  int gated = 0;     // failing factors (each inflated once, in the solve where it failed)
  int resolves = 0;  // solves repeated because a factor failed
};

// Tests every term at the current parameter values and inflates the failing ones; returns how many failed
// (0: nothing changed). Does nothing when !options.enabled.
int GateImuFactors(const GatingOptions& options, const std::vector<ImuTerm>& terms, GatingStats* stats);

}  // namespace vigil::estimator
