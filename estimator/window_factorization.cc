#include "estimator/window_factorization.h"

#include <algorithm>

#include "estimator/window_information.h"

namespace vigil::estimator {
namespace {

// Whether each speed-bias block is coupled (lower triangle) to its neighbours' only.
bool IsSpeedBiasChain(const Eigen::MatrixXd& A, int frames) {
  for (int i = 0; i < frames; ++i)
    for (int j = 0; j + 1 < i; ++j)
      if ((A.block<kSpeedBiasSize, kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(i),
                                                   WindowInformation::SpeedBiasColumn(j))
               .array() != 0.0)
              .any())
        return false;
  return true;
}

// The U x V block of A at (row_u, column_v), read from A's lower triangle (the block at (column_v, row_u)
// transposed when row_u comes first).
template <int U, int V>
Eigen::Matrix<double, U, V> LowerBlock(const Eigen::MatrixXd& A, int row_u, int column_v) {
  if (row_u >= column_v) return A.block<U, V>(row_u, column_v);
  return A.block<V, U>(column_v, row_u).transpose();
}

// dst = LowerBlock(A, row_u, column_v) of sizes U x size_v, size_v kPointSize (a point) or kPoseTangentSize
// (a pose).
template <int U, class Destination>
void CopyLowerBlock(const Eigen::MatrixXd& A, int row_u, int column_v, int size_v, Destination&& dst) {
  if (size_v == kPointSize)
    dst = LowerBlock<U, kPointSize>(A, row_u, column_v);
  else
    dst = LowerBlock<U, kPoseTangentSize>(A, row_u, column_v);
}

}  // namespace

bool WindowFactorization::Compute(const Eigen::MatrixXd& A, int points) {
  frames_ = (static_cast<int>(A.rows()) - kPointSize * points) / WindowInformation::kFrameSize;
  const int n = frames_;
  chain_ =
      A.rows() == A.cols() && A.rows() == WindowInformation::PointColumn(n, points) && IsSpeedBiasChain(A, n);
  if (!chain_) {
    dense_.compute(A);
    return dense_.info() == Eigen::Success;
  }
  // The Schur complement's blocks: the points, then the poses, the newest last.
  schur_blocks_.clear();
  for (int j = 0; j < points; ++j)
    schur_blocks_.push_back({WindowInformation::PointColumn(n, j), kPointSize * j, kPointSize});
  for (int i = 0; i < n; ++i)
    schur_blocks_.push_back(
        {WindowInformation::PoseColumn(i), kPointSize * points + kPoseTangentSize * i, kPoseTangentSize});
  const int schur_columns = kPointSize * points + kPoseTangentSize * n;
  // Its lower triangle, as A holds it.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(schur_columns, schur_columns);
  for (std::size_t v = 0; v < schur_blocks_.size(); ++v)
    for (std::size_t u = v; u < schur_blocks_.size(); ++u) {
      const SchurBlock& bu = schur_blocks_[u];
      const SchurBlock& bv = schur_blocks_[v];
      auto block = S.block(bu.s, bv.s, bu.size, bv.size);
      if (bu.size == kPointSize)
        CopyLowerBlock<kPointSize>(A, bu.a, bv.a, bv.size, block);
      else
        CopyLowerBlock<kPoseTangentSize>(A, bu.a, bv.a, bv.size, block);
    }
  pivots_.resize(n);
  couplings_.resize(n);
  first_schur_column_.resize(n);
  schur_rows_.setZero(kSpeedBiasSize * n, schur_columns);
  // Speed-bias blocks from the newest to the oldest: block k's pivot is reduced by the newer block's
  // elimination, its rows over the Schur complement gain the newer block's fill.
  for (int k = n - 1; k >= 0; --k) {
    auto rows = schur_rows_.middleRows<kSpeedBiasSize>(kSpeedBiasSize * k);
    const int sb = WindowInformation::SpeedBiasColumn(k);
    int first = schur_columns;
    for (const SchurBlock& b : schur_blocks_) {
      auto block = rows.middleCols(b.s, b.size);
      CopyLowerBlock<kSpeedBiasSize>(A, sb, b.a, b.size, block);
      if (first == schur_columns && (block.array() != 0.0).any()) first = b.s;
    }
    SpeedBiasMatrix pivot = A.block<kSpeedBiasSize, kSpeedBiasSize>(sb, sb);
    if (k + 1 < n) {
      // The factor's coupling E = A_(k+1),k^T L_(k+1)^-T, and the newer block's fill E X_(k+1).
      SpeedBiasMatrix& E = couplings_[k];
      E = A.block<kSpeedBiasSize, kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(k + 1), sb).transpose();
      pivots_[k + 1].matrixU().solveInPlace<Eigen::OnTheRight>(E);
      pivot.noalias() -= E * E.transpose();
      first = std::min(first, first_schur_column_[k + 1]);
      const SchurRowsBlock newer = NonzeroSchurRows(k + 1);
      rows.rightCols(newer.cols()).noalias() -= E.lazyProduct(newer);
    }
    pivots_[k].compute(pivot);
    if (pivots_[k].info() != Eigen::Success) return false;
    first_schur_column_[k] = first;
    const int width = schur_columns - first;
    // X = L_k^-1 X by the explicit inverse: a 9-row product, where a triangular solve of this size spends
    // its time in blocking.
    const SpeedBiasMatrix L_inv = pivots_[k].matrixL().solve(SpeedBiasMatrix::Identity());
    const Eigen::Matrix<double, kSpeedBiasSize, Eigen::Dynamic> X = L_inv.lazyProduct(rows.rightCols(width));
    rows.rightCols(width) = X;
    S.bottomRightCorner(width, width).selfadjointView<Eigen::Lower>().rankUpdate(X.transpose(), -1.0);
  }
  schur_.compute(S);
  return schur_.info() == Eigen::Success;
}

WindowFactorization::SchurRowsBlock WindowFactorization::NonzeroSchurRows(int k) const {
  const int first = first_schur_column_[k];
  return SchurRowsBlock(schur_rows_, kSpeedBiasSize * k, first, kSpeedBiasSize, schur_rows_.cols() - first);
}

Eigen::VectorXd WindowFactorization::Solve(const Eigen::VectorXd& b) const {
  if (!chain_) return dense_.solve(b);
  const int n = frames_;
  // Forward: the chain (newest first), then the Schur complement's right-hand side reduced by it.
  Eigen::VectorXd y(kSpeedBiasSize * n), b_schur(schur_rows_.cols());
  for (int k = n - 1; k >= 0; --k) {
    auto y_k = y.segment<kSpeedBiasSize>(kSpeedBiasSize * k);
    y_k = b.segment<kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(k));
    if (k + 1 < n) y_k.noalias() -= couplings_[k] * y.segment<kSpeedBiasSize>(kSpeedBiasSize * (k + 1));
    pivots_[k].matrixL().solveInPlace(y_k);
  }
  for (const SchurBlock& block : schur_blocks_)
    b_schur.segment(block.s, block.size) = b.segment(block.a, block.size);
  for (int k = 0; k < n; ++k) {
    const SchurRowsBlock rows = NonzeroSchurRows(k);
    b_schur.tail(rows.cols()).noalias() -= rows.transpose() * y.segment<kSpeedBiasSize>(kSpeedBiasSize * k);
  }
  const Eigen::VectorXd x_schur = schur_.solve(b_schur);
  // Backward: the chain from the oldest, given the points and poses.
  Eigen::VectorXd x(b.size());
  for (const SchurBlock& block : schur_blocks_)
    x.segment(block.a, block.size) = x_schur.segment(block.s, block.size);
  for (int k = 0; k < n; ++k) {
    const SchurRowsBlock rows = NonzeroSchurRows(k);
    Eigen::Matrix<double, kSpeedBiasSize, 1> x_k = y.segment<kSpeedBiasSize>(kSpeedBiasSize * k);
    x_k.noalias() -= rows * x_schur.tail(rows.cols());
    if (k > 0)
      x_k.noalias() -= couplings_[k - 1].transpose() *
                       x.segment<kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(k - 1));
    pivots_[k].matrixU().solveInPlace(x_k);
    x.segment<kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(k)) = x_k;
  }
  return x;
}

WindowFactorization::PoseMatrix WindowFactorization::NewestPoseCovariance() const {
  const int newest = WindowInformation::PoseColumn(frames_ - 1);
  if (!chain_) {
    Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(dense_.rows(), kPoseTangentSize);
    unit.middleRows<kPoseTangentSize>(newest).setIdentity();
    return dense_.solve(unit).middleRows<kPoseTangentSize>(newest);
  }
  // The newest pose is the last block of the Schur complement's factor: its own Schur complement is
  // L_nn L_nn^T.
  const PoseMatrix L_nn = schur_.matrixLLT()
                              .bottomRightCorner<kPoseTangentSize, kPoseTangentSize>()
                              .triangularView<Eigen::Lower>();
  const PoseMatrix L_inv = L_nn.triangularView<Eigen::Lower>().solve(PoseMatrix::Identity());
  return L_inv.transpose() * L_inv;
}

}  // namespace vigil::estimator
