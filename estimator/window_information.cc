#include "estimator/window_information.h"

#include <utility>

#include "estimator/normal_equations.h"
#include "estimator/robust_loss.h"

namespace vigil::estimator {
namespace {

constexpr int kPose = kPoseTangentSize;
using Vector6d = Eigen::Matrix<double, kPose, 1>;

}  // namespace

WindowInformation::WindowInformation(std::vector<double*> pose_blocks, std::vector<double*> speed_bias_blocks,
                                     std::vector<double*> point_blocks)
    : pose_blocks_(std::move(pose_blocks)),
      speed_bias_blocks_(std::move(speed_bias_blocks)),
      point_blocks_(std::move(point_blocks)) {
  const int n = PointColumn(points());
  H_.setZero(n, n);
  g_.setZero(n);
}

WindowInformation::BlockColumn WindowInformation::ColumnOf(const double* block) const {
  for (int k = 0; k < frames(); ++k) {
    if (pose_blocks_[k] == block) return {PoseColumn(k), kPoseTangentSize};
    if (speed_bias_blocks_[k] == block) return {SpeedBiasColumn(k), kSpeedBiasSize};
  }
  for (int j = 0; j < points(); ++j)
    if (point_blocks_[j] == block) return {PointColumn(j), kPointSize};
  return {};
}

bool WindowInformation::AddFactor(const ceres::CostFunction& cost, const ceres::LossFunction* loss,
                                  const TermBlocks& blocks) {
  const std::vector<int32_t>& sizes = cost.parameter_block_sizes();
  const int rows = cost.num_residuals();
  std::vector<BlockColumn> columns;
  int ambient_total = 0, total = 0;
  for (const double* block : blocks) {
    columns.push_back(ColumnOf(block));
    if (columns.back().column < 0) return false;
    total += columns.back().tangent;
  }
  static const std::vector<int32_t> kTwoFrameBlocks = {kPoseSize, kSpeedBiasSize, kPoseSize, kSpeedBiasSize};
  if (rows == kTwoFrameRows && sizes == kTwoFrameBlocks)
    return AddTwoFrameFactor(cost, loss, blocks, columns);
  static const std::vector<int32_t> kPosePointBlocks = {kPoseSize, kPointSize};
  if (rows == 2 && sizes == kPosePointBlocks && columns[0].tangent == kPose &&
      columns[1].tangent == kPointSize)
    return AddPointObservation(cost, loss, blocks, columns[0].column, columns[1].column);
  for (const int32_t size : sizes) ambient_total += size;
  std::vector<double> jacobian_storage(static_cast<std::size_t>(rows) * ambient_total);
  std::vector<double*> jacobians;
  for (std::size_t k = 0, offset = 0; k < blocks.size(); ++k) {
    jacobians.push_back(jacobian_storage.data() + offset);
    offset += static_cast<std::size_t>(rows) * sizes[k];
  }
  Eigen::VectorXd r(rows);
  if (!cost.Evaluate(blocks.data(), r.data(), jacobians.data()) || !r.allFinite()) return false;
  RowMajorMatrix J(rows, total);
  for (std::size_t k = 0, c = 0; k < blocks.size(); ++k) {
    J.middleCols(c, columns[k].tangent) =
        Eigen::Map<const RowMajorMatrix>(jacobians[k], rows, sizes[k]).leftCols(columns[k].tangent);
    c += columns[k].tangent;
  }
  if (!J.allFinite()) return false;
  Robustify(loss, r, J);
  Accumulate(columns, J.transpose() * J, J.transpose() * r);
  return true;
}

namespace {

// J.middleCols(first_a, A)^T J.middleCols(first_b, B) added to the upper block triangle of H at the blocks'
// window columns (column_a, column_b): at (column_a, column_b) when column_a <= column_b (a diagonal block
// when they are equal), else transposed at (column_b, column_a). A lazy product: at these sizes the blocked
// kernel's set-up costs more than the products.
template <int A, int B, class Jacobian>
void AddUpperBlock(const Jacobian& J, int first_a, int first_b, int column_a, int column_b,
                   Eigen::MatrixXd* H) {
  if (column_a <= column_b)
    H->block<A, B>(column_a, column_b).noalias() +=
        J.template middleCols<A>(first_a).transpose().lazyProduct(J.template middleCols<B>(first_b));
  else
    H->block<B, A>(column_b, column_a).noalias() +=
        J.template middleCols<B>(first_b).transpose().lazyProduct(J.template middleCols<A>(first_a));
}

}  // namespace

bool WindowInformation::AddTwoFrameFactor(const ceres::CostFunction& cost, const ceres::LossFunction* loss,
                                          const TermBlocks& blocks, const std::vector<BlockColumn>& columns) {
  constexpr int kPose = kPoseTangentSize, kSpeedBias = kSpeedBiasSize;
  Eigen::Matrix<double, kTwoFrameRows, kPoseSize, Eigen::RowMajor> J_pose_0, J_pose_1;
  Eigen::Matrix<double, kTwoFrameRows, kSpeedBias, Eigen::RowMajor> J_speed_bias_0, J_speed_bias_1;
  Eigen::Matrix<double, kTwoFrameRows, 1> r;
  double* jacobians[4] = {J_pose_0.data(), J_speed_bias_0.data(), J_pose_1.data(), J_speed_bias_1.data()};
  if (!cost.Evaluate(blocks.data(), r.data(), jacobians) || !r.allFinite()) return false;
  // d r / d [pose 0 tangent, speed-bias 0, pose 1 tangent, speed-bias 1]
  Eigen::Matrix<double, kTwoFrameRows, 2 * kFrameSize, Eigen::RowMajor> J;
  J << J_pose_0.leftCols<kPose>(), J_speed_bias_0, J_pose_1.leftCols<kPose>(), J_speed_bias_1;
  if (!J.allFinite()) return false;
  Robustify(loss, r, J);
  const int p0 = columns[0].column, s0 = columns[1].column, p1 = columns[2].column, s1 = columns[3].column;
  if (p0 == p1 || s0 == s1) return false;  // two frames: distinct blocks
  lower_stale_ = true;
  constexpr int jp0 = 0, js0 = kPose, jp1 = kFrameSize, js1 = kFrameSize + kPose;  // their columns in J
  g_.segment<kPose>(p0).noalias() += J.middleCols<kPose>(jp0).transpose() * r;
  g_.segment<kSpeedBias>(s0).noalias() += J.middleCols<kSpeedBias>(js0).transpose() * r;
  g_.segment<kPose>(p1).noalias() += J.middleCols<kPose>(jp1).transpose() * r;
  g_.segment<kSpeedBias>(s1).noalias() += J.middleCols<kSpeedBias>(js1).transpose() * r;
  // Each pair of blocks once, into the upper block triangle (MirrorUpperTriangles fills the lower one).
  AddUpperBlock<kPose, kPose>(J, jp0, jp0, p0, p0, &H_);
  AddUpperBlock<kPose, kSpeedBias>(J, jp0, js0, p0, s0, &H_);
  AddUpperBlock<kPose, kPose>(J, jp0, jp1, p0, p1, &H_);
  AddUpperBlock<kPose, kSpeedBias>(J, jp0, js1, p0, s1, &H_);
  AddUpperBlock<kSpeedBias, kSpeedBias>(J, js0, js0, s0, s0, &H_);
  AddUpperBlock<kSpeedBias, kPose>(J, js0, jp1, s0, p1, &H_);
  AddUpperBlock<kSpeedBias, kSpeedBias>(J, js0, js1, s0, s1, &H_);
  AddUpperBlock<kPose, kPose>(J, jp1, jp1, p1, p1, &H_);
  AddUpperBlock<kPose, kSpeedBias>(J, jp1, js1, p1, s1, &H_);
  AddUpperBlock<kSpeedBias, kSpeedBias>(J, js1, js1, s1, s1, &H_);
  return true;
}

bool WindowInformation::AddPointObservation(const ceres::CostFunction& cost, const ceres::LossFunction* loss,
                                            const TermBlocks& blocks, int pose, int point) {
  Eigen::Vector2d r;
  Eigen::Matrix<double, 2, kPoseSize, Eigen::RowMajor> J_pose;
  Eigen::Matrix<double, 2, kPointSize, Eigen::RowMajor> J_point;
  double* jacobians[2] = {J_pose.data(), J_point.data()};
  if (!cost.Evaluate(blocks.data(), r.data(), jacobians) || !r.allFinite()) return false;
  Eigen::Matrix<double, 2, kPose + kPointSize, Eigen::RowMajor> J;
  J << J_pose.leftCols<kPose>(), J_point;
  if (!J.allFinite()) return false;
  Robustify(loss, r, J);
  lower_stale_ = true;
  g_.segment<kPose>(pose).noalias() += J.leftCols<kPose>().transpose() * r;
  g_.segment<kPointSize>(point).noalias() += J.rightCols<kPointSize>().transpose() * r;
  // The points follow the frames: the pose's columns come first (the upper block triangle).
  AddUpperBlock<kPose, kPose>(J, 0, 0, pose, pose, &H_);
  AddUpperBlock<kPose, kPointSize>(J, 0, kPose, pose, point, &H_);
  AddUpperBlock<kPointSize, kPointSize>(J, kPose, kPose, point, point, &H_);
  return true;
}

void WindowInformation::Accumulate(const std::vector<BlockColumn>& columns, const Eigen::MatrixXd& H,
                                   const Eigen::VectorXd& g) {
  for (std::size_t a = 0, ca = 0; a < columns.size(); ca += columns[a].tangent, ++a) {
    g_.segment(columns[a].column, columns[a].tangent) += g.segment(ca, columns[a].tangent);
    for (std::size_t b = 0, cb = 0; b < columns.size(); cb += columns[b].tangent, ++b)
      H_.block(columns[a].column, columns[b].column, columns[a].tangent, columns[b].tangent) +=
          H.block(ca, cb, columns[a].tangent, columns[b].tangent);
  }
}

double WindowInformation::EliminatedDepth::Coupling(const Eigen::VectorXd& dx) const {
  double coupling = b_d;
  for (const auto& [column, w_p] : w) coupling += w_p.dot(dx.segment<kPose>(column));
  return coupling;
}

bool WindowInformation::AddTrack(const Reprojection* first, const Reprojection* last,
                                 const ceres::LossFunction* loss, double eigen_threshold,
                                 EliminatedDepth* depth) {
  EliminatedDepth local;
  EliminatedDepth& d = depth ? *depth : local;
  d.h_dd = 0.0;
  d.b_d = 0.0;
  d.w.clear();
  if (first == last) return true;
  lower_stale_ = true;
  // The depth's row of the information: its pivot h_dd, gradient b_d and coupling w to each pose the track
  // involves (its anchor first, then one observing pose per reprojection, each a different frame).
  double h_dd = 0.0, b_d = 0.0;
  std::vector<std::pair<int, Vector6d>>& w = d.w;  // (pose column, d^2 cost / d pose d depth)
  w.reserve(static_cast<std::size_t>(last - first) + 1);
  const auto pose_column = [this](const double* block) {
    const BlockColumn c = ColumnOf(block);
    return c.tangent == kPose ? c.column : -1;
  };
  const int anchor = pose_column(first->blocks[0]);
  if (anchor < 0) return false;
  w.emplace_back(anchor, Vector6d::Zero());
  for (const Reprojection* t = first; t != last; ++t) {
    const int observer = pose_column(t->blocks[1]);
    if (observer < 0 || t->blocks[0] != first->blocks[0] || t->blocks[2] != first->blocks[2]) return false;
    Eigen::Vector2d r;
    Eigen::Matrix<double, 2, kPoseSize, Eigen::RowMajor> J_anchor, J_observer;
    Eigen::Vector2d J_depth;
    double* jacobians[3] = {J_anchor.data(), J_observer.data(), J_depth.data()};
    if (!t->factor->Evaluate(t->blocks.data(), r.data(), jacobians)) return false;
    // d r / d [anchor pose tangent, observing pose tangent, inverse depth].
    Eigen::Matrix<double, 2, 2 * kPose + 1, Eigen::RowMajor> J;
    J << J_anchor.leftCols<kPose>(), J_observer.leftCols<kPose>(), J_depth;
    if (!r.allFinite() || !J.allFinite()) return false;
    Robustify(loss, r, J);
    const auto Ja = J.leftCols<kPose>();
    const auto Jo = J.middleCols<kPose>(kPose);
    const auto Jd = J.col(2 * kPose);
    // The upper block triangle only (MirrorUpperTriangles fills the lower one when it is read).
    H_.block<kPose, kPose>(anchor, anchor).noalias() += Ja.transpose() * Ja;
    H_.block<kPose, kPose>(observer, observer).noalias() += Jo.transpose() * Jo;
    if (anchor < observer) {
      H_.block<kPose, kPose>(anchor, observer).noalias() += Ja.transpose() * Jo;
    } else if (observer < anchor) {
      H_.block<kPose, kPose>(observer, anchor).noalias() += Jo.transpose() * Ja;
    } else {  // a degenerate factor on one pose: both cross terms on its diagonal block
      H_.block<kPose, kPose>(anchor, anchor).noalias() += Ja.transpose() * Jo + Jo.transpose() * Ja;
    }
    g_.segment<kPose>(anchor).noalias() += Ja.transpose() * r;
    g_.segment<kPose>(observer).noalias() += Jo.transpose() * r;
    h_dd += Jd.squaredNorm();
    b_d += Jd.dot(r);
    w.front().second.noalias() += Ja.transpose() * Jd;
    w.emplace_back(observer, Jo.transpose() * Jd);
  }
  // The depth eliminated: H -= w w^T / h_dd, g -= w b_d / h_dd over the track's poses (or the fill +=).
  if (!(h_dd > eigen_threshold)) return true;
  d.h_dd = h_dd;
  d.b_d = b_d;
  // Each unordered pair of the track's poses once, into the upper block triangle.
  for (const auto& [column_p, w_p] : w) {
    const Vector6d f = w_p / h_dd;
    if (separate_fill_) {
      fill_g_.segment<kPose>(column_p) += f * b_d;
      const int fill_p = FillColumn(column_p / kFrameSize);
      for (const auto& [column_q, w_q] : w)
        if (column_q >= column_p)
          fill_H_.block<kPose, kPose>(fill_p, FillColumn(column_q / kFrameSize)).noalias() +=
              f * w_q.transpose();
    } else {
      g_.segment<kPose>(column_p) -= f * b_d;
      for (const auto& [column_q, w_q] : w)
        if (column_q >= column_p) H_.block<kPose, kPose>(column_p, column_q).noalias() -= f * w_q.transpose();
    }
  }
  return true;
}

void WindowInformation::MirrorUpperTriangles() const {
  if (!lower_stale_) return;
  for (Eigen::MatrixXd* m : {&H_, &fill_H_})
    for (Eigen::Index j = 0; j < m->cols(); ++j)
      for (Eigen::Index i = j + 1; i < m->rows(); ++i) (*m)(i, j) = (*m)(j, i);
  lower_stale_ = false;
}

void WindowInformation::SeparateDepthFill() {
  separate_fill_ = true;
  fill_H_.setZero(FillColumn(frames()), FillColumn(frames()));
  fill_g_.setZero(g_.size());
}

void WindowInformation::AddPoseBlocks(const Eigen::MatrixXd& pose_matrix, double scale,
                                      Eigen::MatrixXd* window) {
  const int frames = static_cast<int>(pose_matrix.cols()) / kPose;
  for (int j = 0; j < frames; ++j)
    for (int i = 0; i < frames; ++i)
      window->block<kPose, kPose>(PoseColumn(i), PoseColumn(j)) +=
          scale * pose_matrix.block<kPose, kPose>(FillColumn(i), FillColumn(j));
}

bool WindowInformation::Add(const WindowInformation& other) {
  if (other.pose_blocks_ != pose_blocks_ || other.speed_bias_blocks_ != speed_bias_blocks_ ||
      other.point_blocks_ != point_blocks_ || separate_fill_ || other.separate_fill_)
    return false;
  mutable_H() += other.H();
  g_ += other.g_;
  return true;
}

bool WindowInformation::AddPrior(const LinearPrior& prior) {
  std::vector<BlockColumn> columns;
  for (const LinearPrior::Block& b : prior.blocks) {
    columns.push_back(ColumnOf(b.address));
    if (columns.back().column < 0) return false;
  }
  Eigen::MatrixXd H;
  Eigen::VectorXd g;
  PriorInformationAtCurrentValues(prior, &H, &g);
  Accumulate(columns, H, g);
  return true;
}

}  // namespace vigil::estimator
