// Marginalization: the information that dropped parameter blocks carried, kept as a linear prior.
//
// Marginalize() evaluates every residual block touching the dropped blocks at the current values (robust loss
// applied as Ceres' corrector does), adds the previous prior at the current values, forms H = J^T J and
// b = J^T r over all involved blocks (tangent space), eliminates the dropped ones with the Schur complement
// and stores the result in square-root form J_p, r_p with J_p^T J_p = S (+ a tiny ridge) and
// J_p^T r_p = b_S, so that 1/2 |r_p + J_p dx|^2 reproduces the Schur complement S and its gradient b_S for
// the kept blocks. J_p is the Cholesky factor of S (VINS-Mono stores sqrt(eigenvalues) V^T instead: the same
// quadratic, at a fraction of the cost), so it is upper triangular. MarginalizationFactor evaluates rows of
// r_p + J_p dx with dx = x - x0 in the tangent space (poses: [p - p0, Log(q0^-1 q)]), with the kept blocks at
// their current addresses; PriorFactors() splits the prior by its triangle into one factor per block, which
// halves what the solver evaluates and multiplies out.
//
// Elimination: dropped 1-D blocks that share no residual block with another dropped 1-D block (feature
// inverse depths: each feature's factors touch only its own depth) are eliminated one scalar pivot at a time
// from a sparse row each; the other dropped blocks (the oldest frame's pose and speed-bias) through the
// pseudo-inverse by eigen-decomposition, eigenvalues below `eigen_threshold` dropped. For a positive
// semi-definite H the Schur complement depends neither on the order of elimination nor on the generalized
// inverse used (a pivot at or below the threshold counts as zero, as a dropped eigenvalue does).
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/loss_function.h>
#include <Eigen/Core>

namespace vigil::estimator {

// A term's parameter blocks, held in place: a covariance evaluates about a thousand terms per frame, and a
// vector each would cost an allocation each.
class TermBlocks {
 public:
  static constexpr std::size_t kCapacity = 6;
  TermBlocks() = default;
  TermBlocks(std::initializer_list<double*> blocks) : TermBlocks(blocks.begin(), blocks.end()) {}
  template <class Iterator>
  TermBlocks(Iterator first, Iterator last) {
    for (; first != last; ++first) push_back(*first);
  }
  void push_back(double* block) {
    if (size_ == kCapacity)
      throw std::length_error("a marginalization term has more than 6 parameter blocks");
    blocks_[size_++] = block;
  }
  double* const* data() const { return blocks_.data(); }
  std::size_t size() const { return size_; }
  double* operator[](std::size_t k) const { return blocks_[k]; }
  double* const* begin() const { return blocks_.data(); }
  double* const* end() const { return blocks_.data() + size_; }

 private:
  std::array<double*, kCapacity> blocks_{};
  std::size_t size_ = 0;
};

// One residual block to marginalize (the caller keeps the cost and loss functions alive during Marginalize).
struct MarginalizationTerm {
  const ceres::CostFunction* cost = nullptr;
  const ceres::LossFunction* loss = nullptr;  // may be null
  TermBlocks blocks;
};

// The blocks a marginalization eliminates, in any order (a block no term or prior involves is ignored).
using DroppedBlocks = std::vector<const double*>;

struct LinearPrior {
  struct Block {
    double* address = nullptr;
    int size = 0;     // ambient size (7: pose)
    int tangent = 0;  // tangent size
    std::vector<double> x0;
  };
  std::vector<Block> blocks;
  // rows x sum of tangent sizes, rows <= columns, upper trapezoidal (zero below the diagonal): row i involves
  // the columns from i on only. Empty in a prior built by MarginalizeInformation().
  Eigen::MatrixXd J;
  Eigen::VectorXd r;
  // The same quadratic in information form at x0, H = J^T J and g = J^T r: the next marginalization adds
  // these instead of multiplying out J.
  Eigen::MatrixXd H;
  Eigen::VectorXd g;

  bool Involves(const double* address) const;
};

// A prior's information at its blocks' current values, over its blocks in order (tangent space), as its
// MarginalizationFactor evaluates it: J_x = J D and r_x = r + J dx with D = diag(I, Jr_inv per rotation),
// so H_x = D^T H D and g_x = D^T (g + H dx).
void PriorInformationAtCurrentValues(const LinearPrior& prior, Eigen::MatrixXd* H, Eigen::VectorXd* g);

// The information the kept blocks have once the dropped ones are eliminated (the Schur complement, tangent
// space, at the current values): H symmetric, g its gradient, over `blocks` with their values as x0. The
// prior of Marginalize() is its square-root form; the estimator's pose covariance inverts it.
struct SchurComplement {
  std::vector<LinearPrior::Block> blocks;
  Eigen::MatrixXd H;
  Eigen::VectorXd g;
};

// `previous` (may be null) is the prior so far; it enters at its blocks' current values, exactly as
// MarginalizationFactor would. Returns false when nothing is left to keep or the numbers are not finite.
bool EliminateDropped(const LinearPrior* previous, const std::vector<MarginalizationTerm>& terms,
                      const DroppedBlocks& dropped, double eigen_threshold, SchurComplement* schur);

// The Schur complement A, bk of the symmetric H (its upper triangle read), b over its columns from m on, once
// the first m are eliminated through their pseudo-inverse by eigen-decomposition (eigenvalues at or below
// `eigen_threshold` taken as zero). H and b are left in an unspecified state (with m = 0 they are moved).
void EliminateLeading(Eigen::MatrixXd* H, Eigen::VectorXd* b, int m, double eigen_threshold,
                      Eigen::MatrixXd* A, Eigen::VectorXd* bk);

// How a prior is kept: square-root form (J, r, and H, g), the form a solve evaluates as a factor; or
// information form only (H with the square-root form's ridge, g; J and r empty), for a prior that is only
// read as information (PriorInformationAtCurrentValues).
enum class PriorForm { kSquareRoot, kInformation };

// The prior of a Schur complement in `form`. Square-root form: false when it has no rows or is not finite.
bool PriorOfSchurComplement(SchurComplement schur, double eigen_threshold, PriorForm form,
                            LinearPrior* prior);

// EliminateDropped() in square-root form. The same arguments; false also when the form has no rows.
bool Marginalize(const LinearPrior* previous, const std::vector<MarginalizationTerm>& terms,
                 const DroppedBlocks& dropped, double eigen_threshold, LinearPrior* prior);

// The same prior in information form only (H with Marginalize()'s ridge, g; J and r left empty), without
// the Cholesky factorization, for a prior that is only read as information (PriorInformationAtCurrentValues)
// and never evaluated as a factor: the estimator's anchored prior of the pose covariance. Where Marginalize()
// factorizes (almost always), H and g are the same bits; where it falls back to the eigen-decomposition (a
// Schur complement that is not positive semi-definite to rounding), this one keeps the complement as it is.
bool MarginalizeInformation(const LinearPrior* previous, const std::vector<MarginalizationTerm>& terms,
                            const DroppedBlocks& dropped, double eigen_threshold, LinearPrior* prior);

// Rows [row_begin, row_end) of a prior's r + J dx over its blocks from `first_block` on (J must be zero in
// those rows left of that block's columns); by default all of it.
class MarginalizationFactor : public ceres::CostFunction {
 public:
  explicit MarginalizationFactor(std::shared_ptr<const LinearPrior> prior);
  MarginalizationFactor(std::shared_ptr<const LinearPrior> prior, int first_block, int row_begin,
                        int row_end);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;
  std::vector<double*> parameter_blocks() const;

 private:
  std::shared_ptr<const LinearPrior> prior_;
  int first_block_ = 0;
  int first_column_ = 0;
  int row_begin_ = 0;
};

// The prior as one factor per block k: the rows of J at block k's columns, over blocks k, k + 1, ... (J is
// upper trapezoidal). Together they are the whole prior; blocks past the last row get none.
std::vector<std::unique_ptr<MarginalizationFactor>> PriorFactors(
    const std::shared_ptr<const LinearPrior>& prior);

}  // namespace vigil::estimator
