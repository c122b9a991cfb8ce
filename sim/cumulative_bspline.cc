#include "sim/cumulative_bspline.h"

#include <algorithm>
#include <stdexcept>

#include "core/so3.h"

namespace vigil::sim {

CumulativeBSpline::CumulativeBSpline(std::vector<ControlPoint> control_points, double dt_s)
    : control_points_(std::move(control_points)), dt_s_(dt_s) {
  if (control_points_.size() < 4) throw std::invalid_argument("CumulativeBSpline: at least 4 control points");
  if (!(dt_s_ > 0.0)) throw std::invalid_argument("CumulativeBSpline: knot spacing must be positive");
}

void CumulativeBSpline::Locate(double t_s, int* segment, double* u) const {
  const int last = static_cast<int>(control_points_.size()) - 4;
  const double s = t_s / dt_s_;
  const int i = std::clamp(static_cast<int>(std::floor(s)), 0, last);
  *segment = i;
  *u = s - static_cast<double>(i);
}

CumulativeBSpline::Sample CumulativeBSpline::Evaluate(double t_s) const {
  int i = 0;
  double u = 0.0;
  Locate(t_s, &i, &u);
  const Eigen::Vector4d b = CumulativeBasis(u);
  const Eigen::Vector4d b1 = CumulativeBasisD1(u) / dt_s_;
  const Eigen::Vector4d b2 = CumulativeBasisD2(u) / (dt_s_ * dt_s_);
  const ControlPoint* c = &control_points_[static_cast<std::size_t>(i)];

  Sample x;
  // Position: p_i + sum_j B~_j (p_{i+j} - p_{i+j-1}) and its time derivatives.
  x.p_W = c[0].p_W;
  x.v_W.setZero();
  x.a_W.setZero();
  for (int j = 1; j <= 3; ++j) {
    const Eigen::Vector3d dp = c[j].p_W - c[j - 1].p_W;
    x.p_W += b[j] * dp;
    x.v_W += b1[j] * dp;
    x.a_W += b2[j] * dp;
  }
  // Rotation: R_i prod_j A_j with A_j = Exp(B~_j d_j); body rate by the recursion of the header.
  Eigen::Quaterniond q = c[0].q_WB;
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (int j = 1; j <= 3; ++j) {
    const Eigen::Vector3d d = LogQ(c[j - 1].q_WB.conjugate() * c[j].q_WB);
    const Eigen::Quaterniond A = ExpQ(b[j] * d);
    q = q * A;
    w = A.conjugate() * w + b1[j] * d;
  }
  x.q_WB = q.normalized();
  x.w_B = w;
  return x;
}

}  // namespace vigil::sim
