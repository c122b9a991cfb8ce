#include "estimator/marginalization.h"

#include <cmath>
#include <map>

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
    for (std::size_t k = 0, ck = 0; k < t.blocks.size(); ++k) {
      const int tk = TangentSize(sizes[k]);
      const int col_k = column_of[t.blocks[k]];
      b.segment(col_k, tk) += J.middleCols(ck, tk).transpose() * r;
      for (std::size_t l = 0, cl = 0; l < t.blocks.size(); ++l) {
        const int tl = TangentSize(sizes[l]);
        H.block(col_k, column_of[t.blocks[l]], tk, tl) +=
            J.middleCols(ck, tk).transpose() * J.middleCols(cl, tl);
        cl += tl;
      }
      ck += tk;
    }
  }
  if (!H.allFinite() || !b.allFinite()) return false;

  // Schur complement of the dropped block.
  Eigen::MatrixXd A = H.bottomRightCorner(n, n);
  Eigen::VectorXd bk = b.tail(n);
  if (m > 0) {
    const Eigen::MatrixXd Hmm = 0.5 * (H.topLeftCorner(m, m) + H.topLeftCorner(m, m).transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Hmm);
    const Eigen::VectorXd inv =
        (es.eigenvalues().array() > eigen_threshold).select(es.eigenvalues().array().inverse(), 0.0);
    const Eigen::MatrixXd Hmm_inv = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
    const Eigen::MatrixXd Hkm_Hmm_inv = H.bottomLeftCorner(n, m) * Hmm_inv;
    A -= Hkm_Hmm_inv * H.topRightCorner(m, n);
    bk -= Hkm_Hmm_inv * b.head(m);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (A + A.transpose()));
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
