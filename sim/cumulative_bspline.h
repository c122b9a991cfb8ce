// A uniform cumulative cubic B-spline on SO(3) x R^3: a smooth pose as a function of time, with exact first
// and second derivatives (Lovegrove et al., "Spline Fusion", BMVC 2013; Sommer et al., "Efficient Derivative
// Computation for Cumulative B-Splines on Lie Groups", CVPR 2020).
//
// Knots are uniform: segment i covers [i dt, (i + 1) dt] and depends on the control points i .. i + 3, so
// N control points define N - 3 segments over [0, (N - 3) dt]. With u = t / dt - i in [0, 1] and the
// cumulative basis B~(u) = C [1 u u^2 u^3]^T,
//   B~_1 = (5 + 3u - 3u^2 + u^3) / 6,  B~_2 = (1 + 3u + 3u^2 - 2u^3) / 6,  B~_3 = u^3 / 6,
// the pose is
//   p_W(t)  = p_i + sum_{j=1..3} B~_j(u) (p_{i+j} - p_{i+j-1})
//   R_WB(t) = R_i prod_{j=1..3} Exp(B~_j(u) d_j),   d_j = Log(R_{i+j-1}^T R_{i+j}).
// Position and rotation are splined separately (the split representation), so p_W is the ordinary cubic
// B-spline of the control positions (C2), and R_WB is C2 on SO(3). The body rate w_B = (R^T dR/dt)^v follows
// the recursion w^(0) = 0, w^(j) = A_j^T w^(j-1) + dB~_j/dt d_j with A_j = Exp(B~_j d_j).
//
// The rotation is also provided as a template on the scalar type (SplineRotation), so a fit can
// differentiate it automatically with respect to the control rotations.
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vigil::sim {

// Cumulative basis values B~_1..3 at u (index 0 unused, B~_0 = 1).
inline Eigen::Vector4d CumulativeBasis(double u) {
  const double u2 = u * u, u3 = u2 * u;
  return Eigen::Vector4d(1.0, (5.0 + 3.0 * u - 3.0 * u2 + u3) / 6.0,
                         (1.0 + 3.0 * u + 3.0 * u2 - 2.0 * u3) / 6.0, u3 / 6.0);
}
// dB~_j/du and d^2B~_j/du^2.
inline Eigen::Vector4d CumulativeBasisD1(double u) {
  return Eigen::Vector4d(0.0, (3.0 - 6.0 * u + 3.0 * u * u) / 6.0, (3.0 + 6.0 * u - 6.0 * u * u) / 6.0,
                         0.5 * u * u);
}
inline Eigen::Vector4d CumulativeBasisD2(double u) {
  return Eigen::Vector4d(0.0, (-6.0 + 6.0 * u) / 6.0, (6.0 - 12.0 * u) / 6.0, u);
}

// Exp and Log of SO(3) on unit quaternions for any scalar type (double or an automatic-differentiation jet);
// accurate and differentiable at the identity.
template <class T>
Eigen::Quaternion<T> ExpT(const Eigen::Matrix<T, 3, 1>& phi) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T theta2 = phi.squaredNorm();
  if (theta2 < T(1e-16)) {  // Taylor series; exact to rounding below 1e-8 rad
    const T k = T(0.5) - theta2 / T(48.0);
    return Eigen::Quaternion<T>(T(1.0) - theta2 / T(8.0), k * phi.x(), k * phi.y(), k * phi.z());
  }
  const T theta = sqrt(theta2);
  const T k = sin(T(0.5) * theta) / theta;
  return Eigen::Quaternion<T>(cos(T(0.5) * theta), k * phi.x(), k * phi.y(), k * phi.z());
}

template <class T>
Eigen::Matrix<T, 3, 1> LogT(const Eigen::Quaternion<T>& q_in) {
  using std::atan2;
  using std::sqrt;
  // The short way round: q and -q are the same rotation.
  const Eigen::Quaternion<T> q = q_in.w() < T(0.0) ? Eigen::Quaternion<T>(-q_in.coeffs()) : q_in;
  const T s2 = q.vec().squaredNorm();
  if (s2 < T(1e-20)) return T(2.0) * q.vec() / q.w();  // theta / s = 2 / w (1 + O(s^2))
  const T s = sqrt(s2);
  return (T(2.0) * atan2(s, q.w()) / s) * q.vec();
}

// R_WB(u) of one segment from its four control rotations (unit quaternions).
template <class T>
Eigen::Quaternion<T> SplineRotation(const Eigen::Quaternion<T>& q0, const Eigen::Quaternion<T>& q1,
                                    const Eigen::Quaternion<T>& q2, const Eigen::Quaternion<T>& q3,
                                    double u) {
  const Eigen::Vector4d b = CumulativeBasis(u);
  const Eigen::Quaternion<T>* q[4] = {&q0, &q1, &q2, &q3};
  Eigen::Quaternion<T> r = q0;
  for (int j = 1; j <= 3; ++j) {
    const Eigen::Matrix<T, 3, 1> d = LogT<T>(q[j - 1]->conjugate() * *q[j]);
    r = r * ExpT<T>(T(b[j]) * d);
  }
  return r;
}

class CumulativeBSpline {
 public:
  struct ControlPoint {
    Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
    Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  };
  // The pose and its derivatives at one time.
  struct Sample {
    Eigen::Vector3d p_W, v_W, a_W;
    Eigen::Quaterniond q_WB;
    Eigen::Vector3d w_B;
  };

  // At least 4 control points, knot spacing dt_s > 0.
  CumulativeBSpline(std::vector<ControlPoint> control_points, double dt_s);

  // Evaluates at t_s; times outside [0, EndTime()] are clamped into the first or last segment's polynomial
  // (the spline is not meant to be used there).
  Sample Evaluate(double t_s) const;

  double dt_s() const { return dt_s_; }
  double EndTime() const { return dt_s_ * static_cast<double>(control_points_.size() - 3); }
  const std::vector<ControlPoint>& control_points() const { return control_points_; }

  // The segment of t_s and its local time u in [0, 1].
  void Locate(double t_s, int* segment, double* u) const;

 private:
  std::vector<ControlPoint> control_points_;
  double dt_s_;
};

}  // namespace vigil::sim
