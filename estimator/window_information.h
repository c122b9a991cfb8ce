// The window's information: the Gauss-Newton normal equations H dx = -g of its factors at the current
// estimate, in the tangent space of its states, with every feature's inverse depth eliminated (Schur
// complement), in a fixed layout: frame k's pose tangent [delta p_W, delta theta_B] at column 15 k, its
// speed-bias [v_W, b_a, b_g] at 15 k + 6, and landmark points (if any) after the frames.
//
// It holds what EliminateDropped (marginalization.h) gives for the same factors with the depths dropped, at
// a fraction of the cost: the structure is known, so a track's reprojections are linearized in fixed sizes
// and its depth eliminated over the poses that observe it, with no index maps and no allocation per term.
// The pose covariance (pose_covariance.h) is its marginal (window_factorization.h).
#pragma once

#include <array>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/loss_function.h>
#include <Eigen/Core>

#include "estimator/marginalization.h"
#include "estimator/point_reprojection_factor.h"
#include "estimator/pose_manifold.h"
#include "estimator/reprojection_factor.h"

namespace vigil::estimator {

class WindowInformation {
 public:
  static constexpr int kFrameSize = kPoseTangentSize + kSpeedBiasSize;
  static constexpr int PoseColumn(int frame) { return kFrameSize * frame; }
  static constexpr int SpeedBiasColumn(int frame) { return kFrameSize * frame + kPoseTangentSize; }

  // Zero equations over `frames` frames; `pose_blocks[k]` and `speed_bias_blocks[k]` are frame k's parameter
  // blocks (kPoseSize and kSpeedBiasSize doubles), which the factors name. `point_blocks` (3 doubles each:
  // landmark points in W, window.oldest_tracks points) follow the frames, point j at PointColumn(j).
  WindowInformation(std::vector<double*> pose_blocks, std::vector<double*> speed_bias_blocks,
                    std::vector<double*> point_blocks = {});
  static constexpr int PointColumn(int frames, int point) { return kFrameSize * frames + kPointSize * point; }
  int PointColumn(int point) const { return PointColumn(frames(), point); }

  // Adds a factor over window blocks (each one of the frames' pose or speed-bias blocks), evaluated at their
  // current values with `loss` (may be null) applied. False when the factor fails, a block is not the
  // window's, or the numbers are not finite.
  bool AddFactor(const ceres::CostFunction& cost, const ceres::LossFunction* loss, const TermBlocks& blocks);
  // AddFactor of a marginalization term.
  bool AddTerm(const MarginalizationTerm& term) { return AddFactor(*term.cost, term.loss, term.blocks); }
  // One reprojection of a track: its factor over (anchor pose, observing pose, inverse depth).
  struct Reprojection {
    const ReprojectionFactor* factor;
    std::array<double*, 3> blocks;
  };
  // The eliminated depth's row of the information: its pivot h_dd (0 when the depth was left out), its
  // gradient b_d and its coupling w_p to each pose p of the track, so that its Gauss-Newton step given the
  // states' step dx is d depth = -(b_d + sum_p w_p^T dx_p) / h_dd.
  struct EliminatedDepth {
    double h_dd = 0.0;
    double b_d = 0.0;
    std::vector<std::pair<int, Eigen::Matrix<double, kPoseTangentSize, 1>>> w;  // (pose column, w_p)
    // b_d + sum_p w_p^T dx_p.
    double Coupling(const Eigen::VectorXd& dx) const;
  };
  // Adds every reprojection of one track (all over the same inverse depth, each with `loss`) and eliminates
  // the depth: a pivot at or below `eigen_threshold` counts as no information, and the depth's rows are then
  // left out (as marginalization.h does). `depth` (may be null) receives the depth's row. False when a
  // factor fails, a pose is not the window's, or the numbers are not finite.
  bool AddTrack(const Reprojection* first, const Reprojection* last, const ceres::LossFunction* loss,
                double eigen_threshold, EliminatedDepth* depth = nullptr);
  // Adds a linear prior at its blocks' current values (PriorInformationAtCurrentValues). False when one of
  // its blocks is not the window's.
  bool AddPrior(const LinearPrior& prior);
  // Adds another information over the same blocks (their depth fills folded in as each one's H() holds
  // them). False when the blocks differ.
  bool Add(const WindowInformation& other);
  // From now on, AddTrack adds the depths' elimination (sum over tracks of w w^T / h_dd and w b_d / h_dd)
  // to depth_fill_H() and depth_fill_g() instead of subtracting it from H() and g(): H() - depth_fill_H()
  // is then the information with the depths eliminated. A solve that damps the depths rescales the fill.
  // The depths couple poses only, so depth_fill_H() is over the poses alone (frame k's at FillColumn(k):
  // 96 x 96 for 16 frames, against the window's 240 x 240), added to a window matrix by AddPoseBlocks;
  // depth_fill_g() is in the window's layout.
  void SeparateDepthFill();
  static constexpr int FillColumn(int frame) { return kPoseTangentSize * frame; }
  // window += scale * pose_matrix, pose_matrix over the poses alone (FillColumn), window in the window's
  // layout: each pose block's entries, the others untouched.
  static void AddPoseBlocks(const Eigen::MatrixXd& pose_matrix, double scale, Eigen::MatrixXd* window);
  const Eigen::MatrixXd& depth_fill_H() const {
    MirrorUpperTriangles();
    return fill_H_;
  }
  const Eigen::VectorXd& depth_fill_g() const { return fill_g_; }

  // The first column of a window block and its tangent size; column -1 when it is not the window's.
  struct BlockColumn {
    int column = -1;
    int tangent = 0;
  };
  BlockColumn ColumnOf(const double* block) const;
  int frames() const { return static_cast<int>(pose_blocks_.size()); }
  int points() const { return static_cast<int>(point_blocks_.size()); }
  // Symmetric, both triangles filled.
  const Eigen::MatrixXd& H() const {
    MirrorUpperTriangles();
    return H_;
  }
  Eigen::MatrixXd& mutable_H() {
    MirrorUpperTriangles();
    return H_;
  }
  const Eigen::VectorXd& g() const { return g_; }

 private:
  // AddFactor for a factor of kTwoFrameRows rows over (pose, speed-bias, pose, speed-bias) of two frames (the
  // IMU factor): in fixed sizes, each pair of its blocks once, into the upper block triangle.
  static constexpr int kTwoFrameRows = 15;
  bool AddTwoFrameFactor(const ceres::CostFunction& cost, const ceres::LossFunction* loss,
                         const TermBlocks& blocks, const std::vector<BlockColumn>& columns);
  // AddFactor for a factor of 2 rows over (pose, landmark point) (PointReprojectionFactor), in fixed sizes,
  // into the upper block triangle; `pose` and `point` are the blocks' columns.
  bool AddPointObservation(const ceres::CostFunction& cost, const ceres::LossFunction* loss,
                           const TermBlocks& blocks, int pose, int point);
  // Adds H and g, laid out over `columns` in order (each block's tangent rows), to the window's.
  void Accumulate(const std::vector<BlockColumn>& columns, const Eigen::MatrixXd& H,
                  const Eigen::VectorXd& g);

  // AddTrack and AddTwoFrameFactor add each pair of blocks once, to the upper block triangle of H (AddTrack
  // also of the depth fill: half the products of a track's Schur fill); the accessors copy it to the lower
  // triangle first.
  void MirrorUpperTriangles() const;

  std::vector<double*> pose_blocks_;
  std::vector<double*> speed_bias_blocks_;
  std::vector<double*> point_blocks_;
  mutable Eigen::MatrixXd H_;  // mutable: the lower triangle is filled lazily (MirrorUpperTriangles)
  Eigen::VectorXd g_;
  bool separate_fill_ = false;
  mutable Eigen::MatrixXd fill_H_;
  mutable bool lower_stale_ = false;
  Eigen::VectorXd fill_g_;
};

}  // namespace vigil::estimator
