#include "estimator/marginalization.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "core/so3.h"
#include "estimator/normal_equations.h"
#include "estimator/pose_manifold.h"
#include "estimator/robust_loss.h"

namespace vigil::estimator {
namespace {

// The prior's tangent offset dx = x - x0 at the blocks' current values, and per pose block the inverse right
// Jacobian of its rotation part, d dx_theta / d delta theta (identity for the other blocks).
struct PriorOffset {
  Eigen::VectorXd dx;
  std::vector<Eigen::Matrix3d> Jr_inv;  // per block; used for pose blocks only
};

// Over the blocks from `first_block` on; values[k] is block first_block + k.
PriorOffset OffsetOf(const LinearPrior& prior, int first_block, double const* const* values) {
  PriorOffset o;
  int columns = 0;
  for (std::size_t k = first_block; k < prior.blocks.size(); ++k) columns += prior.blocks[k].tangent;
  o.dx.resize(columns);
  o.Jr_inv.resize(prior.blocks.size() - first_block);
  for (std::size_t k = first_block, c = 0; k < prior.blocks.size(); ++k) {
    const LinearPrior::Block& b = prior.blocks[k];
    const double* x = values[k - first_block];
    if (b.size == kPoseSize) {
      o.dx.segment<3>(c) = PoseP(x) - PoseP(b.x0.data());
      const Eigen::Vector3d phi = LogQ(PoseQ(b.x0.data()).conjugate() * PoseQ(x));
      o.dx.segment<3>(c + 3) = phi;
      o.Jr_inv[k - first_block] = RightJacobianInverse(phi);
    } else {
      for (int i = 0; i < b.size; ++i) o.dx[c + i] = x[i] - b.x0[i];
    }
    c += b.tangent;
  }
  return o;
}

// Pseudo-inverse of a symmetric positive semi-definite matrix by eigen-decomposition, eigenvalues at or below
// `threshold` taken as zero; N: its size if fixed.
template <int N>
Eigen::MatrixXd PseudoInverse(const Eigen::MatrixXd& A, double threshold) {
  using Matrix = Eigen::Matrix<double, N, N>;
  const Eigen::SelfAdjointEigenSolver<Matrix> es{Matrix(A)};
  const auto inv =
      (es.eigenvalues().array() > threshold).select(es.eigenvalues().array().inverse(), 0.0).eval();
  return es.eigenvectors() * inv.matrix().asDiagonal() * es.eigenvectors().transpose();
}

// The ridge a prior's information gets on its diagonal (SquareRootForm, below, says why).
double Ridge(const Eigen::MatrixXd& A, double eigen_threshold) {
  constexpr double kRelativeRidge = 1e-12;
  return eigen_threshold + kRelativeRidge * A.diagonal().cwiseAbs().maxCoeff();
}

// The kept blocks' Schur complement A (symmetric), bk in square-root and information form (J, r, H, g of
// `prior`): Cholesky of A with a ridge, J_p = L^T, r_p = L^-1 bk. The ridge makes the unobservable gauge
// directions factorizable: `eigen_threshold` plus 1e-12 of A's largest diagonal entry (Ridge), at the level
// of the rounding in the Schur complement (its gauge eigenvalues come out within about 1e-11 of that entry,
// either sign). In a 20 s paper run 36 of the 323 priors failed to factorize with the absolute 1e-8 alone, 1
// does with this ridge. An information of 1e-12 of the largest is no constraint at all (paper run: about
// 1e-5, a standard deviation of 300 m or rad). Falls back to the eigen-decomposition (eigenvalues below the
// threshold dropped) if A is not positive semi-definite enough for that. False when nothing is left.
bool SquareRootForm(const Eigen::MatrixXd& A, const Eigen::VectorXd& bk, double eigen_threshold,
                    LinearPrior* prior) {
  const int n = static_cast<int>(A.rows());
  Eigen::MatrixXd A_sym = A;
  const double ridge = Ridge(A_sym, eigen_threshold);
  A_sym.diagonal().array() += ridge;
  Eigen::LLT<Eigen::MatrixXd> llt(A_sym);
  if (llt.info() == Eigen::Success) {
    prior->J = llt.matrixU();
    prior->r = llt.matrixL().solve(bk);
    prior->H = std::move(A_sym);
    prior->g = bk;
  } else {
    A_sym.diagonal().array() -= ridge;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A_sym);
    const Eigen::VectorXd& S = es.eigenvalues();
    std::vector<int> keep;
    for (int i = 0; i < n; ++i)
      if (S[i] > eigen_threshold) keep.push_back(i);
    if (keep.empty()) return false;
    Eigen::MatrixXd J(static_cast<int>(keep.size()), n);
    Eigen::VectorXd r(static_cast<int>(keep.size()));
    for (std::size_t k = 0; k < keep.size(); ++k) {
      const int i = keep[k];
      const double s = std::sqrt(S[i]);
      J.row(static_cast<int>(k)) = s * es.eigenvectors().col(i).transpose();
      r[static_cast<int>(k)] = es.eigenvectors().col(i).dot(bk) / s;
    }
    // J = Q R: |r + J dx| = |Q^T r + R dx| with R upper trapezoidal, as LinearPrior::J must be.
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(J);
    prior->J = qr.matrixQR().triangularView<Eigen::Upper>();
    prior->r = qr.householderQ().transpose() * r;
    prior->H = prior->J.transpose() * prior->J;
    prior->g = prior->J.transpose() * prior->r;
  }
  return true;
}

// The columns of a marginalization: every block in order of first appearance (the previous prior's, then
// the terms'), the uncoupled dropped scalars numbered first, then the other dropped blocks' dense columns
// (m of them), then the kept blocks' (n).
struct Layout {
  std::vector<Column> columns;
  std::unordered_map<const double*, int> index_of;
  std::vector<int> term_columns;         // the terms' blocks' indices into columns, term after term
  std::vector<int> term_columns_offset;  // where term t starts in term_columns (and one past the last term)
  int scalars = 0, m = 0, n = 0;

  IndexRange TermColumns(std::size_t t) const {
    return {term_columns.data() + term_columns_offset[t],
            term_columns_offset[t + 1] - term_columns_offset[t]};
  }
};

Layout LayOut(const LinearPrior* previous, const std::vector<MarginalizationTerm>& terms,
              const DroppedBlocks& dropped) {
  Layout layout;
  std::vector<Column>& columns = layout.columns;
  std::unordered_map<const double*, int>& index_of = layout.index_of;
  index_of.reserve((previous != nullptr ? previous->blocks.size() : 0) + terms.size() + dropped.size());
  auto add = [&](double* address, int ambient) {
    const auto [it, added] = index_of.try_emplace(address, static_cast<int>(columns.size()));
    if (added) {
      Column c;
      c.address = address;
      c.ambient = ambient;
      c.tangent = TangentSizeOf(ambient);
      columns.push_back(c);
    }
    return it->second;
  };
  if (previous != nullptr)
    for (const LinearPrior::Block& b : previous->blocks) columns[add(b.address, b.size)].coupled = true;
  layout.term_columns_offset.reserve(terms.size() + 1);
  layout.term_columns_offset.push_back(0);
  for (const MarginalizationTerm& term : terms) {
    const std::vector<int32_t>& sizes = term.cost->parameter_block_sizes();
    for (std::size_t k = 0; k < term.blocks.size(); ++k)
      layout.term_columns.push_back(add(term.blocks[k], sizes[k]));
    layout.term_columns_offset.push_back(static_cast<int>(layout.term_columns.size()));
  }
  for (const double* address : dropped)
    if (const auto it = index_of.find(address); it != index_of.end()) columns[it->second].dropped = true;
  // A prior is dense over its blocks (marked above); a term with two dropped scalars couples them.
  for (std::size_t t = 0; t < terms.size(); ++t) {
    int dropped_scalars = 0;
    for (const int i : layout.TermColumns(t))
      if (columns[i].dropped && columns[i].tangent == 1) ++dropped_scalars;
    if (dropped_scalars > 1)
      for (const int i : layout.TermColumns(t))
        if (columns[i].tangent == 1) columns[i].coupled = true;
  }
  int &scalars = layout.scalars, &m = layout.m, &n = layout.n;
  for (Column& c : columns)
    if (c.dropped && c.tangent == 1 && !c.coupled) c.scalar = scalars++;
  for (Column& c : columns)
    if (c.dropped && c.scalar < 0) {
      c.column = m;
      m += c.tangent;
    }
  for (Column& c : columns)
    if (!c.dropped) {
      c.column = m + n;
      n += c.tangent;
    }
  return layout;
}

// Adds the previous prior at the blocks' current values (PriorInformationAtCurrentValues).
void AddPreviousPrior(const LinearPrior& previous, const Layout& layout, NormalEquations* eq) {
  Eigen::MatrixXd H;
  Eigen::VectorXd g;
  PriorInformationAtCurrentValues(previous, &H, &g);
  // The prior's blocks are the layout's first columns, in the prior's order.
  std::vector<int> indices(previous.blocks.size());
  std::iota(indices.begin(), indices.end(), 0);
  eq->AddTerm(layout.columns, {indices.data(), static_cast<int>(indices.size())}, H, g);
}

// Evaluates every term at the current values (robust loss applied) and adds its J^T J and J^T r; false when a
// cost function fails or gives a residual or Jacobian that is not finite.
bool AddTerms(const std::vector<MarginalizationTerm>& terms, const Layout& layout, NormalEquations* eq) {
  const std::vector<Column>& columns = layout.columns;
  Eigen::VectorXd r;
  RowMajorMatrix J;  // a term's Jacobian: rows contiguous for the outer products below
  Eigen::MatrixXd JtJ;
  Eigen::VectorXd Jtr;
  std::vector<double> jacobian_storage;
  std::vector<double*> jacobian_ptr;
  for (std::size_t t = 0; t < terms.size(); ++t) {
    const MarginalizationTerm& term = terms[t];
    const std::vector<int32_t>& sizes = term.cost->parameter_block_sizes();
    const int rows = term.cost->num_residuals();
    const IndexRange term_columns = layout.TermColumns(t);
    int ambient_total = 0, total = 0;
    for (const int i : term_columns) {
      ambient_total += columns[i].ambient;
      total += columns[i].tangent;
    }
    r.resize(rows);
    jacobian_storage.resize(static_cast<std::size_t>(rows) * ambient_total);
    jacobian_ptr.clear();
    for (std::size_t k = 0, offset = 0; k < term.blocks.size(); ++k) {
      jacobian_ptr.push_back(jacobian_storage.data() + offset);
      offset += static_cast<std::size_t>(rows) * sizes[k];
    }
    if (!term.cost->Evaluate(term.blocks.data(), r.data(), jacobian_ptr.data()) || !r.allFinite())
      return false;
    J.resize(rows, total);
    for (std::size_t k = 0, c = 0; k < term.blocks.size(); ++k) {
      const int tangent = columns[term_columns.first[k]].tangent;
      J.middleCols(c, tangent) =
          Eigen::Map<const RowMajorMatrix>(jacobian_ptr[k], rows, sizes[k]).leftCols(tangent);
      c += tangent;
    }
    if (!J.allFinite()) return false;
    Robustify(term.loss, r, J);
    // A reprojection (2 x 13: two poses and a depth, most of the terms) in fixed sizes, which the compiler
    // unrolls; other terms of a few rows as a sum of outer products of their rows (vectorized, without the
    // blocked matrix-product kernel and its set-up).
    constexpr int kReprojectionRows = 2, kReprojectionColumns = 2 * kPoseTangentSize + 1;
    if (rows == kReprojectionRows && total == kReprojectionColumns) {
      using Reprojection = Eigen::Matrix<double, kReprojectionRows, kReprojectionColumns, Eigen::RowMajor>;
      const Reprojection Jf = J;
      JtJ.resize(kReprojectionColumns, kReprojectionColumns);
      JtJ.noalias() = Jf.transpose().lazyProduct(Jf);
    } else if (rows <= 4) {
      JtJ.setZero(total, total);
      for (int i = 0; i < rows; ++i) JtJ.noalias() += J.row(i).transpose() * J.row(i);
    } else {
      JtJ.noalias() = J.transpose() * J;
    }
    Jtr.noalias() = J.transpose() * r;
    eq->AddTerm(columns, term_columns, JtJ, Jtr);
  }
  return true;
}

// The kept blocks with their current values as the prior's linearization point x0.
std::vector<LinearPrior::Block> KeptBlocks(const std::vector<Column>& columns) {
  std::vector<LinearPrior::Block> blocks;
  for (const Column& c : columns) {
    if (c.dropped) continue;
    LinearPrior::Block block;
    block.address = c.address;
    block.size = c.ambient;
    block.tangent = c.tangent;
    block.x0.assign(c.address, c.address + c.ambient);
    blocks.push_back(std::move(block));
  }
  return blocks;
}

// EliminateDropped for a prior alone (a frame dropped between keyframes): its information at the current
// values with the dropped blocks' columns first, in the order the general layout gives them.
bool EliminateFromPrior(const LinearPrior& previous, const DroppedBlocks& dropped, double eigen_threshold,
                        SchurComplement* schur) {
  Eigen::MatrixXd H_prior;
  Eigen::VectorXd g_prior;
  PriorInformationAtCurrentValues(previous, &H_prior, &g_prior);
  std::vector<int> first_column(previous.blocks.size());
  for (std::size_t k = 0, c = 0; k < previous.blocks.size(); c += previous.blocks[k].tangent, ++k)
    first_column[k] = static_cast<int>(c);
  auto is_dropped = [&](const LinearPrior::Block& b) {
    return std::find(dropped.begin(), dropped.end(), b.address) != dropped.end();
  };
  std::vector<int> columns;
  int m = 0;
  for (const bool dropped_pass : {true, false})
    for (std::size_t k = 0; k < previous.blocks.size(); ++k) {
      const LinearPrior::Block& b = previous.blocks[k];
      if (is_dropped(b) != dropped_pass) continue;
      for (int i = 0; i < b.tangent; ++i) columns.push_back(first_column[k] + i);
      if (dropped_pass) {
        m += b.tangent;
      } else {
        schur->blocks.push_back(
            {b.address, b.size, b.tangent, std::vector<double>(b.address, b.address + b.size)});
      }
    }
  if (schur->blocks.empty()) return false;
  Eigen::MatrixXd H = H_prior(columns, columns);
  Eigen::VectorXd g = g_prior(columns);
  EliminateLeading(&H, &g, m, eigen_threshold, &schur->H, &schur->g);
  return schur->H.allFinite() && schur->g.allFinite();
}

}  // namespace

void EliminateLeading(Eigen::MatrixXd* H, Eigen::VectorXd* b, int m, double eigen_threshold,
                      Eigen::MatrixXd* A, Eigen::VectorXd* bk) {
  const int n = static_cast<int>(H->rows()) - m;
  if (m == 0) {  // nothing to eliminate: the equations themselves, their lower triangle filled in
    *A = std::move(*H);
    *bk = std::move(*b);
    for (int j = 0; j + 1 < n; ++j) A->col(j).tail(n - j - 1) = A->row(j).tail(n - j - 1).transpose();
    return;
  }
  *A = H->bottomRightCorner(n, n).selfadjointView<Eigen::Upper>();
  *bk = b->tail(n);
  const Eigen::MatrixXd Hmm = H->topLeftCorner(m, m).selfadjointView<Eigen::Upper>();
  // A dropped frame's pose and speed-bias (15) is the usual case: a fixed-size decomposition.
  const Eigen::MatrixXd Hmm_inv = m == kPoseTangentSize + kSpeedBiasSize
                                      ? PseudoInverse<kPoseTangentSize + kSpeedBiasSize>(Hmm, eigen_threshold)
                                      : PseudoInverse<Eigen::Dynamic>(Hmm, eigen_threshold);
  const Eigen::MatrixXd Hkm_Hmm_inv = H->topRightCorner(m, n).transpose() * Hmm_inv;
  A->noalias() -= Hkm_Hmm_inv * H->topRightCorner(m, n);
  bk->noalias() -= Hkm_Hmm_inv * b->head(m);
  *A = (0.5 * (*A + A->transpose())).eval();  // the product is symmetric up to its rounding
}

void PriorInformationAtCurrentValues(const LinearPrior& prior, Eigen::MatrixXd* H, Eigen::VectorXd* g) {
  std::vector<const double*> values;
  for (const LinearPrior::Block& b : prior.blocks) values.push_back(b.address);
  const PriorOffset o = OffsetOf(prior, 0, values.data());
  *H = prior.H;
  *g = prior.g + prior.H * o.dx;
  for (std::size_t k = 0, c = 0; k < prior.blocks.size(); ++k) {
    if (prior.blocks[k].size == kPoseSize) {
      H->middleCols<3>(c + 3) = H->middleCols<3>(c + 3) * o.Jr_inv[k];
      H->middleRows<3>(c + 3) = o.Jr_inv[k].transpose() * H->middleRows<3>(c + 3);
      g->segment<3>(c + 3) = o.Jr_inv[k].transpose() * g->segment<3>(c + 3);
    }
    c += prior.blocks[k].tangent;
  }
}

bool LinearPrior::Involves(const double* address) const {
  for (const Block& b : blocks)
    if (b.address == address) return true;
  return false;
}

bool EliminateDropped(const LinearPrior* previous, const std::vector<MarginalizationTerm>& terms,
                      const DroppedBlocks& dropped, double eigen_threshold, SchurComplement* schur) {
  if (terms.empty() && previous != nullptr)
    return EliminateFromPrior(*previous, dropped, eigen_threshold, schur);
  const Layout layout = LayOut(previous, terms, dropped);
  if (layout.n == 0) return false;
  NormalEquations eq;
  eq.Resize(layout.scalars, layout.m + layout.n, static_cast<int>(layout.columns.size()) - layout.scalars);
  if (previous != nullptr) AddPreviousPrior(*previous, layout, &eq);
  if (!AddTerms(terms, layout, &eq)) return false;
  eq.EliminateScalars(layout.columns, eigen_threshold);
  EliminateLeading(&eq.H, &eq.b, layout.m, eigen_threshold, &schur->H, &schur->g);
  schur->blocks = KeptBlocks(layout.columns);
  return schur->H.allFinite() && schur->g.allFinite();
}

bool PriorOfSchurComplement(SchurComplement schur, double eigen_threshold, PriorForm form,
                            LinearPrior* prior) {
  if (form == PriorForm::kSquareRoot) {
    if (!SquareRootForm(schur.H, schur.g, eigen_threshold, prior)) return false;
    prior->blocks = std::move(schur.blocks);
    return prior->J.allFinite() && prior->r.allFinite();
  }
  const double ridge = Ridge(schur.H, eigen_threshold);
  schur.H.diagonal().array() += ridge;
  prior->blocks = std::move(schur.blocks);
  prior->H = std::move(schur.H);
  prior->g = std::move(schur.g);
  prior->J.resize(0, 0);
  prior->r.resize(0);
  return true;
}

bool Marginalize(const LinearPrior* previous, const std::vector<MarginalizationTerm>& terms,
                 const DroppedBlocks& dropped, double eigen_threshold, LinearPrior* prior) {
  SchurComplement schur;
  return EliminateDropped(previous, terms, dropped, eigen_threshold, &schur) &&
         PriorOfSchurComplement(std::move(schur), eigen_threshold, PriorForm::kSquareRoot, prior);
}

bool MarginalizeInformation(const LinearPrior* previous, const std::vector<MarginalizationTerm>& terms,
                            const DroppedBlocks& dropped, double eigen_threshold, LinearPrior* prior) {
  SchurComplement schur;
  return EliminateDropped(previous, terms, dropped, eigen_threshold, &schur) &&
         PriorOfSchurComplement(std::move(schur), eigen_threshold, PriorForm::kInformation, prior);
}

MarginalizationFactor::MarginalizationFactor(std::shared_ptr<const LinearPrior> prior)
    : MarginalizationFactor(prior, 0, 0, static_cast<int>(prior->r.size())) {}

MarginalizationFactor::MarginalizationFactor(std::shared_ptr<const LinearPrior> prior, int first_block,
                                             int row_begin, int row_end)
    : prior_(std::move(prior)), first_block_(first_block), row_begin_(row_begin) {
  set_num_residuals(row_end - row_begin);
  for (int k = 0; k < first_block; ++k) first_column_ += prior_->blocks[k].tangent;
  for (std::size_t k = first_block; k < prior_->blocks.size(); ++k)
    mutable_parameter_block_sizes()->push_back(prior_->blocks[k].size);
}

std::vector<double*> MarginalizationFactor::parameter_blocks() const {
  std::vector<double*> out;
  for (std::size_t k = first_block_; k < prior_->blocks.size(); ++k) out.push_back(prior_->blocks[k].address);
  return out;
}

bool MarginalizationFactor::Evaluate(double const* const* parameters, double* residuals,
                                     double** jacobians) const {
  const int rows = num_residuals();
  const PriorOffset o = OffsetOf(*prior_, first_block_, parameters);
  const auto J = prior_->J.block(row_begin_, first_column_, rows, o.dx.size());
  Eigen::Map<Eigen::VectorXd>(residuals, rows).noalias() = prior_->r.segment(row_begin_, rows) + J * o.dx;
  if (jacobians == nullptr) return true;
  for (std::size_t k = 0, c = 0; k + first_block_ < prior_->blocks.size(); ++k) {
    const LinearPrior::Block& b = prior_->blocks[k + first_block_];
    if (jacobians[k] != nullptr) {
      Eigen::Map<RowMajorMatrix> jac(jacobians[k], rows, b.size);
      if (b.size == kPoseSize) {
        jac.leftCols<3>() = J.middleCols<3>(c);
        jac.middleCols<3>(3).noalias() = J.middleCols<3>(c + 3) * o.Jr_inv[k];
        jac.col(6).setZero();
      } else {
        jac = J.middleCols(c, b.size);
      }
    }
    c += b.tangent;
  }
  return true;
}

std::vector<std::unique_ptr<MarginalizationFactor>> PriorFactors(
    const std::shared_ptr<const LinearPrior>& prior) {
  std::vector<std::unique_ptr<MarginalizationFactor>> factors;
  const int rows = static_cast<int>(prior->r.size());
  for (std::size_t k = 0, c = 0; k < prior->blocks.size() && static_cast<int>(c) < rows; ++k) {
    const int end = std::min(rows, static_cast<int>(c) + prior->blocks[k].tangent);
    factors.push_back(
        std::make_unique<MarginalizationFactor>(prior, static_cast<int>(k), static_cast<int>(c), end));
    c += prior->blocks[k].tangent;
  }
  return factors;
}

}  // namespace vigil::estimator
