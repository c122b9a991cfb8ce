#include "estimator/init/triangulation.h"

#include <cmath>

#include <Eigen/SVD>

namespace vigil::estimator {

bool TriangulateDlt(const std::vector<Projection>& views, const std::vector<Eigen::Vector2d>& observations,
                    Eigen::Vector3d* p_X) {
  const std::size_t n = views.size();
  if (n < 2 || observations.size() != n) return false;
  Eigen::MatrixXd A(2 * n, 4);
  for (std::size_t i = 0; i < n; ++i) {
    const Projection& P = views[i];
    const Eigen::Index r = static_cast<Eigen::Index>(2 * i);
    A.row(r) = observations[i].x() * P.row(2) - P.row(0);
    A.row(r + 1) = observations[i].y() * P.row(2) - P.row(1);
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::Vector4d X = svd.matrixV().col(3);
  if (std::abs(X[3]) < 1e-12) return false;
  *p_X = X.head<3>() / X[3];
  return p_X->allFinite();
}

}  // namespace vigil::estimator
