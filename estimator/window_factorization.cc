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

// The block of A coupling speed-bias block k to frame j's pose, read from A's lower triangle.
Eigen::Matrix<double, kSpeedBiasSize, kPoseTangentSize> SpeedBiasPoseBlock(const Eigen::MatrixXd& A, int k,
                                                                           int j) {
  if (j <= k)
    return A.block<kSpeedBiasSize, kPoseTangentSize>(WindowInformation::SpeedBiasColumn(k),
                                                     WindowInformation::PoseColumn(j));
  return A
      .block<kPoseTangentSize, kSpeedBiasSize>(WindowInformation::PoseColumn(j),
                                               WindowInformation::SpeedBiasColumn(k))
      .transpose();
}

// The first pose column (in the poses' own numbering, 6 per frame) where speed-bias block k is coupled to a
// pose; the number of pose columns when none.
int FirstCoupledPoseColumn(const Eigen::MatrixXd& A, int k, int frames) {
  for (int j = 0; j < frames; ++j)
    if ((SpeedBiasPoseBlock(A, k, j).array() != 0.0).any()) return kPoseTangentSize * j;
  return kPoseTangentSize * frames;
}

}  // namespace

bool WindowFactorization::Compute(const Eigen::MatrixXd& A) {
  frames_ = static_cast<int>(A.rows()) / WindowInformation::kFrameSize;
  chain_ = A.rows() == A.cols() && A.rows() == WindowInformation::kFrameSize * frames_ &&
           IsSpeedBiasChain(A, frames_);
  if (!chain_) {
    dense_.compute(A);
    return dense_.info() == Eigen::Success;
  }
  const int n = frames_, pose_columns = kPoseTangentSize * n;
  // The poses' block, lower triangle.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(pose_columns, pose_columns);
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; ++i)
      S.block<kPoseTangentSize, kPoseTangentSize>(kPoseTangentSize * i, kPoseTangentSize * j) =
          A.block<kPoseTangentSize, kPoseTangentSize>(WindowInformation::PoseColumn(i),
                                                      WindowInformation::PoseColumn(j));
  pivots_.resize(n);
  couplings_.resize(n);
  first_pose_column_.resize(n);
  pose_rows_.setZero(kSpeedBiasSize * n, pose_columns);
  // Speed-bias blocks from the newest to the oldest: block k's pivot is reduced by the newer block's
  // elimination, its pose rows gain the newer block's fill.
  for (int k = n - 1; k >= 0; --k) {
    int first = FirstCoupledPoseColumn(A, k, n);
    auto rows = pose_rows_.middleRows<kSpeedBiasSize>(kSpeedBiasSize * k);
    for (int j = first / kPoseTangentSize; j < n; ++j)
      rows.middleCols<kPoseTangentSize>(kPoseTangentSize * j) = SpeedBiasPoseBlock(A, k, j);
    SpeedBiasMatrix pivot = A.block<kSpeedBiasSize, kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(k),
                                                                    WindowInformation::SpeedBiasColumn(k));
    if (k + 1 < n) {
      // The factor's coupling E = A_(k+1),k^T L_(k+1)^-T, and the newer block's fill E X_(k+1).
      SpeedBiasMatrix& E = couplings_[k];
      E = A.block<kSpeedBiasSize, kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(k + 1),
                                                  WindowInformation::SpeedBiasColumn(k))
              .transpose();
      pivots_[k + 1].matrixU().solveInPlace<Eigen::OnTheRight>(E);
      pivot.noalias() -= E * E.transpose();
      first = std::min(first, first_pose_column_[k + 1]);
      const PoseRowsBlock newer = NonzeroPoseRows(k + 1);
      rows.rightCols(newer.cols()).noalias() -= E.lazyProduct(newer);
    }
    pivots_[k].compute(pivot);
    if (pivots_[k].info() != Eigen::Success) return false;
    first_pose_column_[k] = first;
    const int width = pose_columns - first;
    // X = L_k^-1 X by the explicit inverse: a 9-row product, where a triangular solve of this size spends
    // its time in blocking.
    const SpeedBiasMatrix L_inv = pivots_[k].matrixL().solve(SpeedBiasMatrix::Identity());
    const Eigen::Matrix<double, kSpeedBiasSize, Eigen::Dynamic> X = L_inv.lazyProduct(rows.rightCols(width));
    rows.rightCols(width) = X;
    S.bottomRightCorner(width, width).selfadjointView<Eigen::Lower>().rankUpdate(X.transpose(), -1.0);
  }
  poses_.compute(S);
  return poses_.info() == Eigen::Success;
}

WindowFactorization::PoseRowsBlock WindowFactorization::NonzeroPoseRows(int k) const {
  const int first = first_pose_column_[k];
  return PoseRowsBlock(pose_rows_, kSpeedBiasSize * k, first, kSpeedBiasSize, pose_rows_.cols() - first);
}

Eigen::VectorXd WindowFactorization::Solve(const Eigen::VectorXd& b) const {
  if (!chain_) return dense_.solve(b);
  const int n = frames_, pose_columns = kPoseTangentSize * n;
  // Forward: the chain (newest first), then the poses' right-hand side reduced by it.
  Eigen::VectorXd y(kSpeedBiasSize * n), b_poses(pose_columns);
  for (int k = n - 1; k >= 0; --k) {
    auto y_k = y.segment<kSpeedBiasSize>(kSpeedBiasSize * k);
    y_k = b.segment<kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(k));
    if (k + 1 < n) y_k.noalias() -= couplings_[k] * y.segment<kSpeedBiasSize>(kSpeedBiasSize * (k + 1));
    pivots_[k].matrixL().solveInPlace(y_k);
  }
  for (int j = 0; j < n; ++j)
    b_poses.segment<kPoseTangentSize>(kPoseTangentSize * j) =
        b.segment<kPoseTangentSize>(WindowInformation::PoseColumn(j));
  for (int k = 0; k < n; ++k) {
    const PoseRowsBlock rows = NonzeroPoseRows(k);
    b_poses.tail(rows.cols()).noalias() -= rows.transpose() * y.segment<kSpeedBiasSize>(kSpeedBiasSize * k);
  }
  const Eigen::VectorXd x_poses = poses_.solve(b_poses);
  // Backward: the chain from the oldest, given the poses.
  Eigen::VectorXd x(b.size());
  for (int k = 0; k < n; ++k) {
    const PoseRowsBlock rows = NonzeroPoseRows(k);
    Eigen::Matrix<double, kSpeedBiasSize, 1> x_k = y.segment<kSpeedBiasSize>(kSpeedBiasSize * k);
    x_k.noalias() -= rows * x_poses.tail(rows.cols());
    if (k > 0)
      x_k.noalias() -= couplings_[k - 1].transpose() *
                       x.segment<kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(k - 1));
    pivots_[k].matrixU().solveInPlace(x_k);
    x.segment<kSpeedBiasSize>(WindowInformation::SpeedBiasColumn(k)) = x_k;
    x.segment<kPoseTangentSize>(WindowInformation::PoseColumn(k)) =
        x_poses.segment<kPoseTangentSize>(kPoseTangentSize * k);
  }
  return x;
}

WindowFactorization::PoseMatrix WindowFactorization::NewestPoseCovariance() const {
  const int newest = WindowInformation::PoseColumn(frames_ - 1);
  if (!chain_) {
    Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(WindowInformation::kFrameSize * frames_, kPoseTangentSize);
    unit.middleRows<kPoseTangentSize>(newest).setIdentity();
    return dense_.solve(unit).middleRows<kPoseTangentSize>(newest);
  }
  // The newest pose is the last column of the poses' factor: its Schur complement is L_nn L_nn^T.
  const PoseMatrix L_nn = poses_.matrixLLT()
                              .bottomRightCorner<kPoseTangentSize, kPoseTangentSize>()
                              .triangularView<Eigen::Lower>();
  const PoseMatrix L_inv = L_nn.triangularView<Eigen::Lower>().solve(PoseMatrix::Identity());
  return L_inv.transpose() * L_inv;
}

}  // namespace vigil::estimator
