#include "estimator/normal_equations.h"

#include <algorithm>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {

void NormalEquations::Resize(int scalars, int dense, int dense_blocks) {
  H = Eigen::MatrixXd::Zero(dense, dense);
  b = Eigen::VectorXd::Zero(dense);
  Hs.resize(scalars, dense);  // not zeroed: a row's block is assigned when the row first reaches it
  h = Eigen::VectorXd::Zero(scalars);
  bs = Eigen::VectorXd::Zero(scalars);
  dense_blocks_ = dense_blocks;
  reach_.resize(static_cast<std::size_t>(scalars) * dense_blocks);
  reach_count_.assign(scalars, 0);
}

IndexRange NormalEquations::ReachOf(int scalar) const {
  return {reach_.data() + static_cast<std::size_t>(scalar) * dense_blocks_, reach_count_[scalar]};
}

void NormalEquations::AddTerm(const std::vector<Column>& columns, IndexRange indices,
                              const Eigen::MatrixXd& JtJ, const Eigen::VectorXd& Jtr) {
  int ck = 0;
  for (const int k : indices) {
    const Column& a = columns[k];
    AddGradient(a, Jtr, ck);
    int cl = 0;
    for (const int l : indices) {
      const Column& c = columns[l];
      Add(a, c, l, JtJ, ck, cl);
      cl += c.tangent;
    }
    ck += a.tangent;
  }
}

void NormalEquations::Add(const Column& k, const Column& l, int l_index, const Eigen::MatrixXd& JtJ, int ck,
                          int cl) {
  if (k.scalar >= 0 && l.scalar >= 0) {
    h[k.scalar] += JtJ(ck, cl);  // the same scalar: uncoupled scalars share no term
  } else if (k.scalar >= 0) {
    auto row_block = Hs.row(k.scalar).segment(l.column, l.tangent);
    const IndexRange r = ReachOf(k.scalar);
    if (std::find(r.begin(), r.end(), l_index) == r.end()) {
      reach_[static_cast<std::size_t>(k.scalar) * dense_blocks_ + reach_count_[k.scalar]++] = l_index;
      row_block = JtJ.block(ck, cl, 1, l.tangent);
    } else {
      row_block += JtJ.block(ck, cl, 1, l.tangent);
    }
  } else if (l.scalar < 0 && k.column <= l.column) {
    if (k.tangent == kPoseTangentSize && l.tangent == kPoseTangentSize)  // pose x pose: fixed size
      H.block<kPoseTangentSize, kPoseTangentSize>(k.column, l.column) +=
          JtJ.block<kPoseTangentSize, kPoseTangentSize>(ck, cl);
    else
      H.block(k.column, l.column, k.tangent, l.tangent) += JtJ.block(ck, cl, k.tangent, l.tangent);
  }
}

void NormalEquations::AddGradient(const Column& k, const Eigen::VectorXd& Jtr, int ck) {
  if (k.scalar >= 0)
    bs[k.scalar] += Jtr[ck];
  else
    b.segment(k.column, k.tangent) += Jtr.segment(ck, k.tangent);
}

void NormalEquations::EliminateScalars(const std::vector<Column>& columns, double threshold) {
  // A block's factor f below: on the stack up to this size (every block of the estimator's), else on the
  // heap.
  constexpr int kStackTangent = 16;
  using StackVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kStackTangent, 1>;
  for (int s = 0; s < static_cast<int>(h.size()); ++s) {
    if (!(h[s] > threshold)) continue;
    const IndexRange reach = ReachOf(s);
    for (const int i : reach) {
      const Column& a = columns[i];
      // With f = Hs(s, a)^T / h[s]: b_a -= f bs[s], H(a, c) -= f Hs(s, c) for the reached blocks c.
      auto subtract = [&](const auto& f) {
        b.segment(a.column, a.tangent) -= f * bs[s];
        for (const int j : reach) {
          const Column& c = columns[j];
          if (a.column > c.column) continue;
          if (a.tangent == kPoseTangentSize && c.tangent == kPoseTangentSize)  // pose x pose: fixed size
            H.block<kPoseTangentSize, kPoseTangentSize>(a.column, c.column).noalias() -=
                f.template head<kPoseTangentSize>() * Hs.row(s).segment<kPoseTangentSize>(c.column);
          else
            H.block(a.column, c.column, a.tangent, c.tangent).noalias() -=
                f * Hs.row(s).segment(c.column, c.tangent);
        }
      };
      const auto f = (Hs.row(s).segment(a.column, a.tangent) / h[s]).transpose();
      if (a.tangent <= kStackTangent)
        subtract(StackVector(f));
      else
        subtract(Eigen::VectorXd(f));
    }
  }
}

}  // namespace vigil::estimator
