#include "estimator/imu_gating.h"

#include <cmath>

#include <Eigen/Core>

namespace vigil::estimator {
namespace {

// P(a, x), the regularized lower incomplete gamma function, by its power series (converges for every x; the
// gate's arguments are a = 7.5, x < 100).
double RegularizedLowerGamma(double a, double x) {
  if (x <= 0.0) return 0.0;
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 1000 && term > sum * 1e-16; ++n) {
    term *= x / (a + n);
    sum += term;
  }
  return std::exp(a * std::log(x) - x - std::lgamma(a)) * sum;
}

}  // namespace

double ChiSquareQuantile(int dof, double p) {
  const double a = 0.5 * dof;
  double lo = 0.0, hi = dof + 20.0 * std::sqrt(2.0 * dof) + 100.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (RegularizedLowerGamma(a, 0.5 * mid) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

int GateImuFactors(const GatingOptions& options, const std::vector<ImuTerm>& terms, GatingStats* stats) {
  if (!options.enabled) return 0;
  const double threshold = ChiSquareQuantile(15, options.quantile);
  int gated = 0;
  for (const ImuTerm& term : terms) {
    Eigen::Matrix<double, 15, 1> r;
    if (!term.factor->Evaluate(term.blocks.data(), r.data(), nullptr)) continue;
    ++stats->tests;
    const double chi2 = r.squaredNorm();
    if (!(chi2 > threshold)) continue;
    const double inflation = options.variance_factor > 0.0 ? options.variance_factor : chi2 / threshold;
    term.factor->InflateCovariance(inflation);
    ++gated;
  }
  stats->gated += gated;
  if (gated > 0) ++stats->resolves;
  return gated;
}

}  // namespace vigil::estimator
