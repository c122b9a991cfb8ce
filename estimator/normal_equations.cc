#include "estimator/normal_equations.h"

#include <algorithm>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {

void NormalEquations::Resize(int scalars, int dense, int dense_blocks) {
  H = Eigen::MatrixXd::Zero(dense, dense);
  b = Eigen::VectorXd::Zero(dense);
  Hs = Eigen::MatrixXd::Zero(scalars, dense);
  h = Eigen::VectorXd::Zero(scalars);
  bs = Eigen::VectorXd::Zero(scalars);
  reach.assign(scalars, {});
  for (std::vector<int>& r : reach) r.reserve(dense_blocks);
}

void NormalEquations::AddTerm(const std::vector<Column>& columns, const std::vector<int>& indices,
                              const Eigen::MatrixXd& JtJ, const Eigen::VectorXd& Jtr) {
  for (std::size_t k = 0, ck = 0; k < indices.size(); ++k) {
    const Column& a = columns[indices[k]];
    AddGradient(a, Jtr, static_cast<int>(ck));
    for (std::size_t l = 0, cl = 0; l < indices.size(); ++l) {
      const Column& c = columns[indices[l]];
      Add(a, c, indices[l], JtJ, static_cast<int>(ck), static_cast<int>(cl));
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
    Hs.row(k.scalar).segment(l.column, l.tangent) += JtJ.block(ck, cl, 1, l.tangent);
    std::vector<int>& r = reach[k.scalar];
    if (std::find(r.begin(), r.end(), l_index) == r.end()) r.push_back(l_index);
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
  for (int s = 0; s < static_cast<int>(h.size()); ++s) {
    if (!(h[s] > threshold)) continue;
    for (const int i : reach[s]) {
      const Column& a = columns[i];
      const auto f = (Hs.row(s).segment(a.column, a.tangent) / h[s]).transpose().eval();
      b.segment(a.column, a.tangent) -= f * bs[s];
      for (const int j : reach[s]) {
        const Column& c = columns[j];
        if (a.column > c.column) continue;
        if (a.tangent == kPoseTangentSize && c.tangent == kPoseTangentSize)  // pose x pose: fixed size
          H.block<kPoseTangentSize, kPoseTangentSize>(a.column, c.column).noalias() -=
              f.head<kPoseTangentSize>() * Hs.row(s).segment<kPoseTangentSize>(c.column);
        else
          H.block(a.column, c.column, a.tangent, c.tangent).noalias() -=
              f * Hs.row(s).segment(c.column, c.tangent);
      }
    }
  }
}

}  // namespace vigil::estimator
