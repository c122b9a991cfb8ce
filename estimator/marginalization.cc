#include "estimator/marginalization.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "core/so3.h"
#include "estimator/pose_manifold.h"

namespace vigil::estimator {
namespace {

int TangentSize(int ambient) { return ambient == kPoseSize ? kPoseTangentSize : ambient; }

// Applies a robust loss to a residual and its Jacobian like Ceres' Corrector (second-order aware).
void Robustify(const ceres::LossFunction* loss, Eigen::VectorXd* r, Eigen::MatrixXd* J) {
  if (loss == nullptr) return;
  const double s = r->squaredNorm();
  double rho[3];
  loss->Evaluate(s, rho);
  const double sqrt_rho1 = std::sqrt(rho[1]);
  if (s == 0.0 || rho[2] <= 0.0) {
    *r *= sqrt_rho1;
    *J *= sqrt_rho1;
    return;
  }
  const double D = 1.0 + 2.0 * s * rho[2] / rho[1];
  const double alpha = 1.0 - std::sqrt(D);
  const Eigen::VectorXd r0 = *r;
  *J = sqrt_rho1 * (*J - alpha / s * r0 * (r0.transpose() * *J));
  *r = sqrt_rho1 / (1.0 - alpha) * r0;
}

// How many of the leading dropped blocks are 1-D and coupled to no other of them in H (their columns come
// first).
int LeadingUncoupledScalars(const Eigen::MatrixXd& H, const std::vector<double*>& order_dropped,
                            const std::map<const double*, int>& ambient_of) {
  int scalars = 0;
  while (scalars < static_cast<int>(order_dropped.size()) &&
         TangentSize(ambient_of.at(order_dropped[scalars])) == 1)
    ++scalars;
  for (int i = 0; i < scalars; ++i)
    for (int j = 0; j < scalars; ++j)
      if (i != j && H(i, j) != 0.0) return 0;
  return scalars;
}

}  // namespace

bool LinearPrior::Involves(const double* address) const {
  for (const Block& b : blocks)
    if (b.address == address) return true;
  return false;
}

bool Marginalize(const std::vector<MarginalizationTerm>& terms, const std::set<const double*>& dropped,
                 double eigen_threshold, LinearPrior* prior) {
  // Column layout: dropped blocks first, then kept blocks, each in order of first appearance.
  std::map<const double*, int> ambient_of;
  std::vector<double*> order_dropped, order_kept;
  for (const MarginalizationTerm& t : terms) {
    const std::vector<int32_t>& sizes = t.cost->parameter_block_sizes();
    for (std::size_t k = 0; k < t.blocks.size(); ++k) {
      if (ambient_of.emplace(t.blocks[k], sizes[k]).second)
        (dropped.count(t.blocks[k]) ? order_dropped : order_kept).push_back(t.blocks[k]);
    }
  }
  // Dropped 1-D blocks (feature inverse depths) first: the Schur step below takes them one pivot at a time.
  std::stable_partition(order_dropped.begin(), order_dropped.end(),
                        [&](const double* b) { return TangentSize(ambient_of[b]) == 1; });
  std::map<const double*, int> column_of;
  int m = 0;
  for (double* b : order_dropped) {
    column_of[b] = m;
    m += TangentSize(ambient_of[b]);
  }
  int n = 0;
  for (double* b : order_kept) {
    column_of[b] = m + n;
    n += TangentSize(ambient_of[b]);
  }
  if (n == 0) return false;

  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m + n, m + n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m + n);
  for (const MarginalizationTerm& t : terms) {
    const std::vector<int32_t>& sizes = t.cost->parameter_block_sizes();
    const int rows = t.cost->num_residuals();
    Eigen::VectorXd r(rows);
    std::vector<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> jac(t.blocks.size());
    std::vector<double*> jac_ptr(t.blocks.size());
    int total = 0;
    for (std::size_t k = 0; k < t.blocks.size(); ++k) {
      jac[k].resize(rows, sizes[k]);
      jac_ptr[k] = jac[k].data();
      total += TangentSize(sizes[k]);
    }
    if (!t.cost->Evaluate(t.blocks.data(), r.data(), jac_ptr.data())) return false;
    Eigen::MatrixXd J(rows, total);
    for (std::size_t k = 0, c = 0; k < t.blocks.size(); ++k) {
      const int tangent = TangentSize(sizes[k]);
      J.middleCols(c, tangent) = jac[k].leftCols(tangent);
      c += tangent;
    }
    Robustify(t.loss, &r, &J);
    // Small terms (a reprojection: 2 x 13) skip the blocked matrix-product kernel and its set-up.
    const Eigen::MatrixXd JtJ = rows * total <= 64 ? Eigen::MatrixXd(J.transpose().lazyProduct(J))
                                                   : Eigen::MatrixXd(J.transpose() * J);
    const Eigen::VectorXd Jtr = J.transpose() * r;
    for (std::size_t k = 0, ck = 0; k < t.blocks.size(); ++k) {
      const int tk = TangentSize(sizes[k]);
      const int col_k = column_of[t.blocks[k]];
      b.segment(col_k, tk) += Jtr.segment(ck, tk);
      for (std::size_t l = 0, cl = 0; l < t.blocks.size(); ++l) {
        const int tl = TangentSize(sizes[l]);
        H.block(col_k, column_of[t.blocks[l]], tk, tl) += JtJ.block(ck, cl, tk, tl);
        cl += tl;
      }
      ck += tk;
    }
  }
  if (!H.allFinite() || !b.allFinite()) return false;

  // Schur complement of the dropped blocks. The leading scalar columns that couple to no other scalar column
  // (inverse depths: each feature's factors touch only its own depth) are eliminated one pivot at a time,
  // touching only the entries their column reaches; the remaining dropped columns (the oldest frame's pose
  // and speed-bias) by the eigen-decomposition. For a positive semi-definite H the Schur complement does not
  // depend on the order of elimination nor on the generalized inverse used (pivots at or below the threshold
  // count as zero, as dropped eigenvalues do).
  const int scalars = LeadingUncoupledScalars(H, order_dropped, ambient_of);
  for (int i = 0; i < scalars; ++i) {
    const double pivot = H(i, i);
    if (!(pivot > eigen_threshold)) continue;
    std::vector<int> reach;
    for (int j = scalars; j < m + n; ++j)
      if (H(j, i) != 0.0) reach.push_back(j);
    for (const int j : reach) {
      const double f = H(j, i) / pivot;
      for (const int k : reach) H(j, k) -= f * H(i, k);
      b[j] -= f * b[i];
    }
  }
  const int rest = m - scalars;
  Eigen::MatrixXd A = H.bottomRightCorner(n, n);
  Eigen::VectorXd bk = b.tail(n);
  if (rest > 0) {
    const Eigen::MatrixXd Hmm =
        0.5 * (H.block(scalars, scalars, rest, rest) + H.block(scalars, scalars, rest, rest).transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Hmm);
    const Eigen::VectorXd inv =
        (es.eigenvalues().array() > eigen_threshold).select(es.eigenvalues().array().inverse(), 0.0);
    const Eigen::MatrixXd Hmm_inv = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
    const Eigen::MatrixXd Hkm_Hmm_inv = H.block(m, scalars, n, rest) * Hmm_inv;
    A -= Hkm_Hmm_inv * H.block(scalars, m, rest, n);
    bk -= Hkm_Hmm_inv * b.segment(scalars, rest);
  }
  // Square-root form of the kept block: Cholesky of A with a ridge of `eigen_threshold` (an information of
  // 1e-8 is no constraint at all but makes the unobservable gauge directions factorizable), J_p = L^T,
  // r_p = L^-1 b. Falls back to the eigen-decomposition (eigenvalues below the threshold dropped) if A is not
  // positive semi-definite enough for that.
  const Eigen::MatrixXd A_sym = 0.5 * (A + A.transpose());
  Eigen::LLT<Eigen::MatrixXd> llt(A_sym + eigen_threshold * Eigen::MatrixXd::Identity(n, n));
  if (llt.info() == Eigen::Success) {
    prior->J = llt.matrixU();
    prior->r = llt.matrixL().solve(bk);
  } else {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A_sym);
    const Eigen::VectorXd& S = es.eigenvalues();
    std::vector<int> keep;
    for (int i = 0; i < n; ++i)
      if (S[i] > eigen_threshold) keep.push_back(i);
    if (keep.empty()) return false;
    prior->J.resize(static_cast<int>(keep.size()), n);
    prior->r.resize(static_cast<int>(keep.size()));
    for (std::size_t k = 0; k < keep.size(); ++k) {
      const int i = keep[k];
      const double s = std::sqrt(S[i]);
      prior->J.row(static_cast<int>(k)) = s * es.eigenvectors().col(i).transpose();
      prior->r[static_cast<int>(k)] = es.eigenvectors().col(i).dot(bk) / s;
    }
  }
  prior->blocks.clear();
  for (double* address : order_kept) {
    LinearPrior::Block block;
    block.address = address;
    block.size = ambient_of[address];
    block.tangent = TangentSize(block.size);
    block.x0.assign(address, address + block.size);
    prior->blocks.push_back(std::move(block));
  }
  return prior->J.allFinite() && prior->r.allFinite();
}

MarginalizationFactor::MarginalizationFactor(std::shared_ptr<const LinearPrior> prior)
    : prior_(std::move(prior)) {
  set_num_residuals(static_cast<int>(prior_->r.size()));
  for (const LinearPrior::Block& b : prior_->blocks) mutable_parameter_block_sizes()->push_back(b.size);
}

std::vector<double*> MarginalizationFactor::parameter_blocks() const {
  std::vector<double*> out;
  for (const LinearPrior::Block& b : prior_->blocks) out.push_back(b.address);
  return out;
}

bool MarginalizationFactor::Evaluate(double const* const* parameters, double* residuals,
                                     double** jacobians) const {
  const int rows = static_cast<int>(prior_->r.size());
  const int n = static_cast<int>(prior_->J.cols());
  Eigen::VectorXd dx(n);
  std::vector<Eigen::Matrix3d> Jr_inv(prior_->blocks.size());
  for (std::size_t k = 0, c = 0; k < prior_->blocks.size(); ++k) {
    const LinearPrior::Block& b = prior_->blocks[k];
    const double* x = parameters[k];
    if (b.size == kPoseSize) {
      dx.segment<3>(c) = PoseP(x) - PoseP(b.x0.data());
      const Eigen::Vector3d phi = LogQ(PoseQ(b.x0.data()).conjugate() * PoseQ(x));
      dx.segment<3>(c + 3) = phi;
      Jr_inv[k] = RightJacobianInverse(phi);
    } else {
      for (int i = 0; i < b.size; ++i) dx[c + i] = x[i] - b.x0[i];
    }
    c += b.tangent;
  }
  Eigen::Map<Eigen::VectorXd>(residuals, rows) = prior_->r + prior_->J * dx;
  if (jacobians == nullptr) return true;
  for (std::size_t k = 0, c = 0; k < prior_->blocks.size(); ++k) {
    const LinearPrior::Block& b = prior_->blocks[k];
    if (jacobians[k] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> jac(jacobians[k],
                                                                                             rows, b.size);
      jac.setZero();
      if (b.size == kPoseSize) {
        jac.leftCols<3>() = prior_->J.middleCols<3>(c);
        jac.middleCols<3>(3) = prior_->J.middleCols<3>(c + 3) * Jr_inv[k];
      } else {
        jac = prior_->J.middleCols(c, b.size);
      }
    }
    c += b.tangent;
  }
  return true;
}

}  // namespace vigil::estimator
