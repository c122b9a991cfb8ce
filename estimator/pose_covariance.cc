#include "estimator/pose_covariance.h"

#include <cmath>
#include <numeric>
#include <utility>

#include <Eigen/Cholesky>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {
namespace {

// The square root of the gauge information in the pose tangent: position, and the world yaw
// delta yaw = e_z^T R_WB delta theta_B.
Eigen::Matrix<double, 4, 6> GaugeRows(const Eigen::Quaterniond& q_WB) {
  const double root = std::sqrt(kGaugeInformation);
  Eigen::Matrix<double, 4, 6> J = Eigen::Matrix<double, 4, 6>::Zero();
  J.topLeftCorner<3, 3>() = root * Eigen::Matrix3d::Identity();
  J.block<1, 3>(3, 3) = root * Eigen::Vector3d::UnitZ().transpose() * q_WB.toRotationMatrix();
  return J;
}

// Block elimination of a symmetric information matrix down to one block: which blocks are coupled
// (nonzero off-diagonal block, fill included) and which are still to be eliminated.
class BlockElimination {
 public:
  BlockElimination(Eigen::MatrixXd H, const std::vector<int>& block_sizes)
      : H_(std::move(H)),
        size_(block_sizes),
        start_(block_sizes.size() + 1, 0),
        alive_(block_sizes.size(), true) {
    std::partial_sum(size_.begin(), size_.end(), start_.begin() + 1);
    const int n = static_cast<int>(size_.size());
    coupled_.assign(n, std::vector<bool>(n, false));
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) coupled_[i][j] = coupled_[j][i] = (Block(i, j).array() != 0.0).any();
  }

  int BlockAt(int column) const {
    for (std::size_t k = 0; k < size_.size(); ++k)
      if (start_[k] == column) return static_cast<int>(k);
    return -1;
  }

  // The living block other than `target` with the fewest coupled dimensions, or -1 when the living blocks
  // are all coupled to each other (nothing is left to gain from their sparsity).
  int SparsestBlock(int target) const {
    int best = -1, best_degree = 0;
    for (std::size_t k = 0; k < size_.size(); ++k) {
      if (!alive_[k] || static_cast<int>(k) == target) continue;
      const int degree = Degree(static_cast<int>(k));
      if (best < 0 || degree < best_degree) {
        best = static_cast<int>(k);
        best_degree = degree;
      }
    }
    int living = 0;
    for (std::size_t k = 0; k < size_.size(); ++k)
      if (alive_[k]) living += size_[k];
    return best >= 0 && best_degree + size_[best] < living ? best : -1;
  }

  // Eliminates block k (Schur complement onto its coupled blocks); false when its pivot is not positive
  // definite.
  bool Eliminate(int k) {
    const std::vector<int> neighbours = Neighbours(k);
    std::vector<int> columns;
    for (const int j : neighbours)
      for (int c = start_[j]; c < start_[j + 1]; ++c) columns.push_back(c);
    const Eigen::LLT<Eigen::MatrixXd> pivot(Block(k, k));
    if (pivot.info() != Eigen::Success) return false;
    alive_[k] = false;
    if (columns.empty()) return true;  // an uncoupled block: nothing to update
    Eigen::MatrixXd W = H_(Eigen::seqN(start_[k], size_[k]), columns);
    pivot.matrixL().solveInPlace(W);
    H_(columns, columns) -= W.transpose() * W;
    for (const int a : neighbours)
      for (const int b : neighbours)
        if (a != b) coupled_[a][b] = true;
    return true;
  }

  // The Cholesky factor L_tt of the living blocks' Schur complement onto `target` (S = L_tt L_tt^T), from
  // a dense factorization of the living blocks with `target` last. False when they are not positive
  // definite.
  bool TargetFactor(int target, Matrix6d* L_tt) const {
    std::vector<int> columns;
    for (std::size_t k = 0; k < size_.size(); ++k)
      if (alive_[k] && static_cast<int>(k) != target)
        for (int c = start_[k]; c < start_[k + 1]; ++c) columns.push_back(c);
    for (int c = start_[target]; c < start_[target + 1]; ++c) columns.push_back(c);
    const Eigen::LLT<Eigen::MatrixXd> llt(H_(columns, columns));
    if (llt.info() != Eigen::Success) return false;
    *L_tt = llt.matrixLLT().bottomRightCorner<6, 6>().triangularView<Eigen::Lower>();
    return true;
  }

 private:
  Eigen::Block<Eigen::MatrixXd> Block(int i, int j) {
    return H_.block(start_[i], start_[j], size_[i], size_[j]);
  }
  Eigen::Block<const Eigen::MatrixXd> Block(int i, int j) const {
    return H_.block(start_[i], start_[j], size_[i], size_[j]);
  }
  std::vector<int> Neighbours(int k) const {
    std::vector<int> out;
    for (std::size_t j = 0; j < size_.size(); ++j)
      if (alive_[j] && coupled_[k][j]) out.push_back(static_cast<int>(j));
    return out;
  }
  int Degree(int k) const {
    int degree = 0;
    for (std::size_t j = 0; j < size_.size(); ++j)
      if (alive_[j] && coupled_[k][j]) degree += size_[j];
    return degree;
  }

  Eigen::MatrixXd H_;
  std::vector<int> size_, start_;
  std::vector<bool> alive_;
  std::vector<std::vector<bool>> coupled_;
};

}  // namespace

LinearPrior GaugePrior(double* pose) {
  LinearPrior prior;
  prior.blocks.push_back({pose, kPoseSize, kPoseTangentSize, std::vector<double>(pose, pose + kPoseSize)});
  prior.J = GaugeRows(PoseQ(pose).normalized());
  prior.r = Eigen::VectorXd::Zero(4);
  prior.H = prior.J.transpose() * prior.J;
  prior.g = Eigen::VectorXd::Zero(kPoseTangentSize);
  return prior;
}

void AddGaugeInformation(const Eigen::Quaterniond& q_WB, int column, Eigen::MatrixXd* H) {
  const Eigen::Matrix<double, 4, 6> J = GaugeRows(q_WB);
  H->block<6, 6>(column, column) += J.transpose() * J;
}

bool MarginalPoseCovariance(Eigen::MatrixXd H, const std::vector<int>& block_sizes, int column,
                            Matrix6d* covariance) {
  BlockElimination elimination(std::move(H), block_sizes);
  const int target = elimination.BlockAt(column);
  if (target < 0 || block_sizes[target] != kPoseTangentSize) return false;
  for (int k = elimination.SparsestBlock(target); k >= 0; k = elimination.SparsestBlock(target))
    if (!elimination.Eliminate(k)) return false;
  Matrix6d L_tt;
  if (!elimination.TargetFactor(target, &L_tt)) return false;
  // S^-1 = L_tt^-T L_tt^-1.
  const Matrix6d L_inv = L_tt.triangularView<Eigen::Lower>().solve(Matrix6d::Identity());
  *covariance = L_inv.transpose() * L_inv;
  return covariance->allFinite();
}

}  // namespace vigil::estimator
