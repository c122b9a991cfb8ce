// The normal equations of a marginalization (marginalization.h), split for sparse elimination.
//
// Every parameter block is a Column. Dropped 1-D blocks that share no residual block with another dropped 1-D
// block (feature inverse depths) are "scalars": each has a sparse row of its own (its diagonal entry h[s],
// its row Hs.row(s) over the dense columns, the dense blocks that row reaches and its gradient bs[s]; only
// the reached blocks of a row are set, the rest of Hs is never written nor read); every other block has
// columns in the dense part H, b (the other dropped blocks first), of which H holds the blocks on and above
// the diagonal only (the lower ones are never read).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace vigil::estimator {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A run of column indices stored elsewhere (a term's blocks, a scalar's reach).
struct IndexRange {
  const int* first = nullptr;
  int count = 0;
  const int* begin() const { return first; }
  const int* end() const { return first + count; }
};

// A parameter block of the normal equations: a sparse row of its own (`scalar`) or columns in the dense part
// (`column`).
struct Column {
  double* address = nullptr;
  int ambient = 0;
  int tangent = 0;
  bool dropped = false;
  bool coupled = false;  // a dropped 1-D block that cannot be a scalar pivot
  int scalar = -1;
  int column = -1;
};

struct NormalEquations {
  Eigen::MatrixXd H;
  RowMajorMatrix Hs;
  Eigen::VectorXd b, h, bs;

  // The dense blocks (indices into the columns) a scalar's row reaches, in the order first reached.
  IndexRange ReachOf(int scalar) const;

  // Zero equations of `scalars` sparse rows and `dense` columns in `dense_blocks` blocks.
  void Resize(int scalars, int dense, int dense_blocks);
  // Adds a term's J^T J and J^T r, whose columns are those of `indices` (into `columns`) in that order.
  void AddTerm(const std::vector<Column>& columns, IndexRange indices, const Eigen::MatrixXd& JtJ,
               const Eigen::VectorXd& Jtr);
  // Adds the block (k, l) of a term's J^T J whose columns start at ck, cl (l is the column l_index).
  void Add(const Column& k, const Column& l, int l_index, const Eigen::MatrixXd& JtJ, int ck, int cl);
  void AddGradient(const Column& k, const Eigen::VectorXd& Jtr, int ck);
  // Eliminates every scalar with a pivot above `threshold` (the others count as zero), block by block over
  // the dense blocks its row reaches: H, b become the Schur complement of the scalars.
  void EliminateScalars(const std::vector<Column>& columns, double threshold);

 private:
  // Per scalar a fixed slot of dense_blocks_ entries (one allocation for all, not one per scalar).
  std::vector<int> reach_;
  std::vector<int> reach_count_;
  int dense_blocks_ = 0;
};

}  // namespace vigil::estimator
