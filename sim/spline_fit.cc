#include "sim/spline_fit.h"

#include <algorithm>
#include <cmath>

#include <ceres/ceres.h>

#include "core/so3.h"

namespace vigil::sim {
namespace {

// r = p(t_k) - p_k, from the segment's four control positions.
struct PositionResidual {
  PositionResidual(double u, const Eigen::Vector3d& p) : b(CumulativeBasis(u)), p_W(p) {}
  template <class T>
  bool operator()(const T* c0, const T* c1, const T* c2, const T* c3, T* r) const {
    const T* c[4] = {c0, c1, c2, c3};
    for (int a = 0; a < 3; ++a) {
      T p = c0[a];
      for (int j = 1; j <= 3; ++j) p += T(b[j]) * (c[j][a] - c[j - 1][a]);
      r[a] = p - T(p_W[a]);
    }
    return true;
  }
  Eigen::Vector4d b;
  Eigen::Vector3d p_W;
};

// r = Log(R(t_k)^T R_k), from the segment's four control rotations (Eigen quaternions, x y z w).
struct RotationResidual {
  RotationResidual(double u_in, const Eigen::Quaterniond& q) : u(u_in), q_WB(q) {}
  template <class T>
  bool operator()(const T* c0, const T* c1, const T* c2, const T* c3, T* r) const {
    using Q = Eigen::Quaternion<T>;
    const Q q = SplineRotation<T>(Eigen::Map<const Q>(c0), Eigen::Map<const Q>(c1), Eigen::Map<const Q>(c2),
                                  Eigen::Map<const Q>(c3), u);
    Eigen::Map<Eigen::Matrix<T, 3, 1>> residual(r);
    residual = LogT<T>(q.conjugate() * q_WB.cast<T>());
    return true;
  }
  double u;
  Eigen::Quaterniond q_WB;
};

// r = w (p_{i-1} - 2 p_i + p_{i+1}).
struct PositionSmoothness {
  explicit PositionSmoothness(double w) : weight(w) {}
  template <class T>
  bool operator()(const T* a, const T* b, const T* c, T* r) const {
    for (int k = 0; k < 3; ++k) r[k] = T(weight) * (a[k] - T(2.0) * b[k] + c[k]);
    return true;
  }
  double weight;
};

// r = w (Log(R_{i-1}^T R_i) - Log(R_i^T R_{i+1})).
struct RotationSmoothness {
  explicit RotationSmoothness(double w) : weight(w) {}
  template <class T>
  bool operator()(const T* a, const T* b, const T* c, T* r) const {
    using Q = Eigen::Quaternion<T>;
    const Eigen::Map<const Q> qa(a), qb(b), qc(c);
    Eigen::Map<Eigen::Matrix<T, 3, 1>> residual(r);
    residual = T(weight) * (LogT<T>(Q(qa.conjugate() * qb)) - LogT<T>(Q(qb.conjugate() * qc)));
    return true;
  }
  double weight;
};

// The recorded pose interpolated at t_s (linear / slerp between neighbours, clamped at the ends): the
// starting point of the fit.
CumulativeBSpline::ControlPoint Interpolated(const std::vector<SplineFitPose>& poses, double t_s) {
  CumulativeBSpline::ControlPoint c;
  if (t_s <= poses.front().t_s) {
    c.p_W = poses.front().p_W;
    c.q_WB = poses.front().q_WB;
    return c;
  }
  if (t_s >= poses.back().t_s) {
    c.p_W = poses.back().p_W;
    c.q_WB = poses.back().q_WB;
    return c;
  }
  const auto next = std::upper_bound(poses.begin(), poses.end(), t_s,
                                     [](double t, const SplineFitPose& p) { return t < p.t_s; });
  const SplineFitPose& b = *next;
  const SplineFitPose& a = *(next - 1);
  const double s = (t_s - a.t_s) / (b.t_s - a.t_s);
  c.p_W = (1.0 - s) * a.p_W + s * b.p_W;
  c.q_WB = a.q_WB * ExpQ(s * LogQ(a.q_WB.conjugate() * b.q_WB));
  return c;
}

}  // namespace

CumulativeBSpline FitCumulativeBSpline(const std::vector<SplineFitPose>& poses, double dt_s,
                                       double smoothing) {
  // Segments cover [0, span]; control point i + 1 sits at the start of segment i (its largest weight).
  const double span_s = poses.back().t_s;
  const int segments = std::max(1, static_cast<int>(std::ceil(span_s / dt_s - 1e-9)));
  const int n = segments + 3;
  std::vector<CumulativeBSpline::ControlPoint> control(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    control[static_cast<std::size_t>(i)] = Interpolated(poses, (i - 1) * dt_s);
    if (i > 0 &&
        control[static_cast<std::size_t>(i)].q_WB.dot(control[static_cast<std::size_t>(i - 1)].q_WB) < 0)
      control[static_cast<std::size_t>(i)].q_WB.coeffs() *= -1.0;  // a continuous sign (cosmetic)
  }
  const CumulativeBSpline layout(control, dt_s);

  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ceres::EigenQuaternionManifold quaternion_manifold;
  const auto p = [&](int i) { return control[static_cast<std::size_t>(i)].p_W.data(); };
  const auto q = [&](int i) { return control[static_cast<std::size_t>(i)].q_WB.coeffs().data(); };
  for (const SplineFitPose& pose : poses) {
    int i = 0;
    double u = 0.0;
    layout.Locate(pose.t_s, &i, &u);
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PositionResidual, 3, 3, 3, 3, 3>(new PositionResidual(u, pose.p_W)),
        nullptr, p(i), p(i + 1), p(i + 2), p(i + 3));
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<RotationResidual, 3, 4, 4, 4, 4>(new RotationResidual(u, pose.q_WB)),
        nullptr, q(i), q(i + 1), q(i + 2), q(i + 3));
  }
  for (int i = 1; i + 1 < n; ++i) {
    if (smoothing <= 0.0) break;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PositionSmoothness, 3, 3, 3, 3>(new PositionSmoothness(smoothing)),
        nullptr, p(i - 1), p(i), p(i + 1));
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<RotationSmoothness, 3, 4, 4, 4>(new RotationSmoothness(smoothing)),
        nullptr, q(i - 1), q(i), q(i + 1));
  }
  for (int i = 0; i < n; ++i)
    if (problem.HasParameterBlock(q(i))) problem.SetManifold(q(i), &quaternion_manifold);
  // A control point that no residual reaches (smoothing 0 and a gap in the poses) keeps its interpolated
  // value.

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = 50;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  for (auto& c : control) c.q_WB.normalize();
  return CumulativeBSpline(std::move(control), dt_s);
}

}  // namespace vigil::sim
