#include "estimator/init/pnp.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "core/so3.h"

namespace vigil::estimator {

Eigen::Vector2d PnpResidual(const Eigen::Matrix3d& R_CX, const Eigen::Vector3d& p_CX,
                            const Eigen::Vector3d& p_X, const Eigen::Vector2d& observation,
                            Eigen::Matrix<double, 2, 6>* J) {
  const Eigen::Vector3d Rp = R_CX * p_X;
  const Eigen::Vector3d p_C = Rp + p_CX;
  const double iz = 1.0 / p_C.z();
  if (J) {
    Eigen::Matrix<double, 2, 3> d_proj;
    d_proj << iz, 0, -p_C.x() * iz * iz, 0, iz, -p_C.y() * iz * iz;
    // d(Exp(dtheta) R p) / d dtheta = -[R p]x.
    J->leftCols<3>() = -d_proj * Skew(Rp);
    J->rightCols<3>() = d_proj;
  }
  return p_C.head<2>() * iz - observation;
}

bool SolvePnp(const std::vector<Eigen::Vector3d>& points_X, const std::vector<Eigen::Vector2d>& observations,
              const PnpOptions& options, Eigen::Matrix3d* R_CX, Eigen::Vector3d* p_CX) {
  if (points_X.size() < 4 || observations.size() != points_X.size()) return false;
  auto cost_of = [&](const Eigen::Matrix3d& R, const Eigen::Vector3d& p, int* used) {
    double c = 0.0;
    *used = 0;
    for (std::size_t i = 0; i < points_X.size(); ++i) {
      if ((R * points_X[i] + p).z() < options.min_depth) continue;
      c += PnpResidual(R, p, points_X[i], observations[i], nullptr).squaredNorm();
      ++*used;
    }
    return c;
  };
  Eigen::Matrix3d R = *R_CX;
  Eigen::Vector3d p = *p_CX;
  int used = 0;
  double cost = cost_of(R, p, &used);
  if (used < 4) return false;
  double lambda = 1e-4;
  for (int it = 0; it < options.max_iterations; ++it) {
    Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t i = 0; i < points_X.size(); ++i) {
      if ((R * points_X[i] + p).z() < options.min_depth) continue;
      Eigen::Matrix<double, 2, 6> J;
      const Eigen::Vector2d r = PnpResidual(R, p, points_X[i], observations[i], &J);
      H += J.transpose() * J;
      g += J.transpose() * r;
    }
    bool improved = false;
    for (int attempt = 0; attempt < 10 && !improved; ++attempt) {
      Eigen::Matrix<double, 6, 6> Hd = H;
      Hd.diagonal() *= 1.0 + lambda;
      const Eigen::Matrix<double, 6, 1> dx = -Hd.ldlt().solve(g);
      const Eigen::Matrix3d R_new = ExpQ(dx.head<3>()).toRotationMatrix() * R;
      const Eigen::Vector3d p_new = p + dx.tail<3>();
      int used_new = 0;
      const double cost_new = cost_of(R_new, p_new, &used_new);
      if (std::isfinite(cost_new) && used_new >= 4 && cost_new <= cost) {
        improved = true;
        const bool converged = cost - cost_new < 1e-14 * (1.0 + cost) || dx.norm() < 1e-12;
        R = R_new;
        p = p_new;
        cost = cost_new;
        lambda = std::max(lambda / 10.0, 1e-9);
        if (converged) it = options.max_iterations;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved) break;
  }
  if (!R.allFinite() || !p.allFinite()) return false;
  *R_CX = R;
  *p_CX = p;
  return true;
}

}  // namespace vigil::estimator
