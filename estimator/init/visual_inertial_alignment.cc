#include "estimator/init/visual_inertial_alignment.h"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "core/format.h"
#include "core/so3.h"

namespace vigil::estimator {
namespace {

// Rows of the alignment equations of pair (i, i + 1) for the unknowns [v_0 .. v_{n-1}, gravity part, s].
// The gravity part is g_L itself (3 columns) when `G` is the identity, or the tangent coordinates w (2
// columns) of g_L = g0 + G w. Returns the normal equations accumulated over all pairs.
template <int kGravityCols>
bool SolveAlignment(const std::vector<AlignmentFrame>& frames, const Eigen::Vector3d& p_BC,
                    const Eigen::Vector3d& g0, const Eigen::Matrix<double, 3, kGravityCols>& G,
                    Eigen::VectorXd* x) {
  const int n = static_cast<int>(frames.size());
  const int dim = 3 * n + kGravityCols + 1;
  const int gcol = 3 * n, scol = 3 * n + kGravityCols;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(dim, dim);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(dim);
  for (int i = 0; i + 1 < n; ++i) {
    const AlignmentFrame& fi = frames[static_cast<std::size_t>(i)];
    const AlignmentFrame& fj = frames[static_cast<std::size_t>(i + 1)];
    const Preintegration& pre = *fj.imu_from_prev;
    const double T = pre.sum_dt_s();
    // Local unknowns [v_i (3), v_j (3), gravity (kGravityCols), s (1)].
    Eigen::Matrix<double, 6, 7 + kGravityCols> A = Eigen::Matrix<double, 6, 7 + kGravityCols>::Zero();
    Eigen::Matrix<double, 6, 1> r;
    A.template block<3, 3>(0, 0) = -T * Eigen::Matrix3d::Identity();
    A.template block<3, kGravityCols>(0, 6) = -0.5 * T * T * G;
    A.template block<3, 1>(0, 6 + kGravityCols) = fj.p_LC - fi.p_LC;
    r.head<3>() = fi.R_LB * pre.delta_p() + (fj.R_LB - fi.R_LB) * p_BC + 0.5 * T * T * g0;
    A.template block<3, 3>(3, 0) = -Eigen::Matrix3d::Identity();
    A.template block<3, 3>(3, 3) = Eigen::Matrix3d::Identity();
    A.template block<3, kGravityCols>(3, 6) = -T * G;
    r.tail<3>() = fi.R_LB * pre.delta_v() + T * g0;
    const Eigen::Matrix<double, 7 + kGravityCols, 7 + kGravityCols> h = A.transpose() * A;
    const Eigen::Matrix<double, 7 + kGravityCols, 1> g = A.transpose() * r;
    // Scatter into the global system: local blocks [v_i v_j] -> 3i, gravity -> gcol, s -> scol.
    const int starts[3] = {3 * i, gcol, scol};
    const int local[3] = {0, 6, 6 + kGravityCols};
    const int sizes[3] = {6, kGravityCols, 1};
    for (int a = 0; a < 3; ++a) {
      b.segment(starts[a], sizes[a]) += g.segment(local[a], sizes[a]);
      for (int c = 0; c < 3; ++c)
        H.block(starts[a], starts[c], sizes[a], sizes[c]) += h.block(local[a], local[c], sizes[a], sizes[c]);
    }
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(H);
  if (qr.rank() < dim) return false;
  *x = qr.solve(b);
  return x->allFinite();
}

void Unpack(const Eigen::VectorXd& x, int n, Alignment* alignment) {
  alignment->v_L.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) alignment->v_L[static_cast<std::size_t>(k)] = x.segment<3>(3 * k);
  alignment->scale = x[x.size() - 1];
}

bool HasImu(const std::vector<AlignmentFrame>& frames) {
  if (frames.size() < 2) return false;
  for (std::size_t k = 1; k < frames.size(); ++k)
    if (frames[k].imu_from_prev == nullptr) return false;
  return true;
}

// Log(dq_k(b_g)^-1 R_LB_{k-1}^T R_LB_k): the rotation of pair (k-1, k) that the bias-corrected gyroscope and
// the vision disagree on. Needs frames[k].imu_from_prev.
Eigen::Vector3d PairRotationResidual(const std::vector<AlignmentFrame>& frames, std::size_t k,
                                     const Eigen::Vector3d& b_g) {
  const Eigen::Quaterniond q_vision(frames[k - 1].R_LB.transpose() * frames[k].R_LB);
  return LogQ(frames[k].imu_from_prev->CorrectedDeltaQ(b_g).conjugate() * q_vision);
}

}  // namespace

void TangentBasis(const Eigen::Vector3d& n, Eigen::Vector3d* b1, Eigen::Vector3d* b2) {
  const Eigen::Vector3d helper = std::abs(n.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  *b1 = n.cross(helper).normalized();
  *b2 = n.cross(*b1);
}

bool SolveGyroBias(const std::vector<AlignmentFrame>& frames, const Eigen::Vector3d& b_g_start,
                   int iterations, Eigen::Vector3d* b_g) {
  if (!HasImu(frames)) return false;
  Eigen::Vector3d bias = b_g_start;
  for (int it = 0; it < iterations; ++it) {
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (std::size_t k = 1; k < frames.size(); ++k) {
      // Right perturbation: dq(b_g + d) ~ dq(b_g) Exp(J d), J = d theta / d b_g.
      const Eigen::Vector3d r = PairRotationResidual(frames, k, bias);
      const Eigen::Matrix3d J = frames[k].imu_from_prev->jacobian().block<3, 3>(kDtheta, kBg);
      H += J.transpose() * J;
      g += J.transpose() * r;
    }
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(H);
    if (ldlt.info() != Eigen::Success || !(H.determinant() > 0.0)) return false;
    const Eigen::Vector3d delta = ldlt.solve(g);
    if (!delta.allFinite()) return false;
    bias += delta;
    if (delta.norm() < 1e-9) break;
  }
  *b_g = bias;
  return true;
}

std::vector<double> GyroRotationResiduals(const std::vector<AlignmentFrame>& frames,
                                          const Eigen::Vector3d& b_g) {
  std::vector<double> residuals_rad;
  if (!HasImu(frames)) return residuals_rad;
  for (std::size_t k = 1; k < frames.size(); ++k)
    residuals_rad.push_back(PairRotationResidual(frames, k, b_g).norm());
  return residuals_rad;
}

bool LinearAlignment(const std::vector<AlignmentFrame>& frames, const Eigen::Vector3d& p_BC,
                     double gravity_mps2, double max_gravity_error_mps2, Alignment* alignment,
                     std::string* why) {
  if (!HasImu(frames)) {
    *why = "alignment needs two frames and IMU between every pair";
    return false;
  }
  Eigen::VectorXd x;
  if (!SolveAlignment<3>(frames, p_BC, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), &x)) {
    *why = "linear alignment is singular";
    return false;
  }
  const int n = static_cast<int>(frames.size());
  Unpack(x, n, alignment);
  alignment->g_L = x.segment<3>(3 * n);
  if (!(alignment->scale > 0.0)) {
    *why = "linear alignment: non-positive scale " + FormatDouble(alignment->scale);
    return false;
  }
  if (!(std::abs(alignment->g_L.norm() - gravity_mps2) <= max_gravity_error_mps2)) {
    *why = "linear alignment: |g| = " + FormatFixed(alignment->g_L.norm(), 3) + " m/s^2";
    return false;
  }
  return true;
}

bool RefineGravity(const std::vector<AlignmentFrame>& frames, const Eigen::Vector3d& p_BC,
                   double gravity_mps2, int iterations, Alignment* alignment, std::string* why) {
  if (!HasImu(frames) || !(alignment->g_L.norm() > 0.0)) {
    *why = "gravity refinement needs IMU between every pair and an initial gravity";
    return false;
  }
  const int n = static_cast<int>(frames.size());
  Eigen::Vector3d g = alignment->g_L.normalized() * gravity_mps2;
  for (int it = 0; it < iterations; ++it) {
    Eigen::Vector3d b1, b2;
    TangentBasis(g.normalized(), &b1, &b2);
    Eigen::Matrix<double, 3, 2> B;
    B << b1, b2;
    Eigen::VectorXd x;
    if (!SolveAlignment<2>(frames, p_BC, g, B, &x)) {
      *why = "gravity refinement is singular";
      return false;
    }
    Unpack(x, n, alignment);
    g = (g + B * x.segment<2>(3 * n)).normalized() * gravity_mps2;
  }
  alignment->g_L = g;
  if (!(alignment->scale > 0.0)) {
    *why = "gravity refinement: non-positive scale " + FormatDouble(alignment->scale);
    return false;
  }
  return true;
}

}  // namespace vigil::estimator
