// A robust loss applied to a residual and its Jacobian as Ceres' Corrector does (second-order aware), for
// the normal equations vigil builds itself (marginalization, the window's information).
//
// For a loss rho(s), s = |r|^2, the corrected r~ and J~ give the loss's Gauss-Newton model:
// J~^T J~ = rho' J^T (I + 2 rho''/rho' r r^T) J and J~^T r~ = rho' J^T r.
#pragma once

#include <cmath>

#include <ceres/loss_function.h>
#include <Eigen/Core>

namespace vigil::estimator {

// `r` and `J` are Eigen vectors and matrices of the same number of rows (fixed or dynamic sizes).
template <class Residual, class Jacobian>
void Robustify(const ceres::LossFunction* loss, Eigen::MatrixBase<Residual>& r,
               Eigen::MatrixBase<Jacobian>& J) {
  if (loss == nullptr) return;
  const double s = r.squaredNorm();
  double rho[3];
  loss->Evaluate(s, rho);
  const double sqrt_rho1 = std::sqrt(rho[1]);
  if (s == 0.0 || rho[2] <= 0.0) {
    r *= sqrt_rho1;
    J *= sqrt_rho1;
    return;
  }
  const double D = 1.0 + 2.0 * s * rho[2] / rho[1];
  const double alpha = 1.0 - std::sqrt(D);
  const typename Residual::PlainObject r0 = r;
  J = sqrt_rho1 * (J - (alpha / s) * r0 * (r0.transpose() * J));
  r = (sqrt_rho1 / (1.0 - alpha)) * r0;
}

}  // namespace vigil::estimator
