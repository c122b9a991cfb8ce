// The window's normal equations factorized in the order its structure makes cheap.
//
// In WindowInformation's layout (frame k's pose tangent at column 15 k, its speed-bias at 15 k + 6), the
// poses are coupled to one another by the features, but each speed-bias block only to its neighbours' (the
// IMU factors) and to a few poses: the marginalization prior reaches the oldest frame's, the IMU factors
// the poses of the frame and its neighbours. So the speed-bias blocks are eliminated first, as a chain from
// the newest to the oldest, and only the poses' Schur complement (96 of a 16-frame window's 240 dimensions)
// is factorized densely, the newest pose last. Eliminated in that order, the newest speed-bias block fills
// in only the last poses' columns, the next one a few more, and so on: the multiply-adds fall from a dense
// Cholesky factorization's 240^3 / 6 to about a quarter of that. The factor's last 6x6 block is the Cholesky
// factor of the newest pose's Schur complement, whose inverse is that pose's marginal covariance.
//
// Landmark points (window.oldest_tracks points), 3 columns each after the frames, join the poses in that
// Schur complement, ahead of them, so that the newest pose stays last: the prior couples the points to one
// another and to the oldest frame's states, and the chain's elimination fills their columns like the poses'.
//
// A matrix whose speed-bias blocks are coupled beyond their neighbours is factorized densely instead: the
// results are the same, only slower.
#pragma once

#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {

class WindowFactorization {
 public:
  using PoseMatrix = Eigen::Matrix<double, kPoseTangentSize, kPoseTangentSize>;

  // Factorizes the symmetric `A` over whole frames of WindowInformation's layout, then `points` landmark
  // points; only its lower triangle is read. False when `A` is not positive definite.
  bool Compute(const Eigen::MatrixXd& A, int points = 0);
  // x with A x = b.
  Eigen::VectorXd Solve(const Eigen::VectorXd& b) const;
  // The newest frame's pose block of A^-1: the newest pose's marginal covariance, when A is the window's
  // information.
  PoseMatrix NewestPoseCovariance() const;
  // Whether the speed-bias chain was eliminated first (false: a dense factorization).
  bool chain() const { return chain_; }

 private:
  using SpeedBiasMatrix = Eigen::Matrix<double, kSpeedBiasSize, kSpeedBiasSize>;
  using SchurRowsBlock = Eigen::Block<const Eigen::MatrixXd, kSpeedBiasSize, Eigen::Dynamic>;
  // A block of the Schur complement: its first column in A and in the Schur complement, and its size.
  struct SchurBlock {
    int a = 0;
    int s = 0;
    int size = 0;
  };

  // Speed-bias block k's rows of the factor over the Schur complement's columns, from its first nonzero
  // column on.
  SchurRowsBlock NonzeroSchurRows(int k) const;

  int frames_ = 0;
  bool chain_ = false;
  // The points' and the poses' blocks, in the Schur complement's order (the points first).
  std::vector<SchurBlock> schur_blocks_;
  // The chain: the Cholesky factor of each speed-bias block's pivot, and the factor's block coupling it to
  // the next newer one (row k, column k + 1).
  std::vector<Eigen::LLT<SpeedBiasMatrix>> pivots_;
  std::vector<SpeedBiasMatrix> couplings_;
  // The factor's rows of speed-bias block k over the Schur complement's columns (9 rows per block), nonzero
  // from column first_schur_column_[k] on.
  Eigen::MatrixXd schur_rows_;
  std::vector<int> first_schur_column_;
  // The Schur complement of the points and the poses, factorized.
  Eigen::LLT<Eigen::MatrixXd> schur_;
  // The dense factorization, when the speed-bias blocks do not form a chain.
  Eigen::LLT<Eigen::MatrixXd> dense_;
};

}  // namespace vigil::estimator
