// Marginalization: the information that dropped parameter blocks carried, kept as a linear prior.
//
// Marginalize() evaluates every residual block touching the dropped blocks at the current values (robust loss
// applied as Ceres' corrector does), forms H = J^T J and b = J^T r over all involved blocks (tangent space),
// eliminates the dropped ones with the Schur complement (pseudo-inverse of H_mm by eigen-decomposition,
// eigenvalues below `eigen_threshold` dropped), and stores the result as J_p = sqrt(S) V^T and
// r_p = sqrt(S)^-1 V^T b, so that 1/2 |r_p + J_p dx|^2 reproduces H and b for the kept blocks.
// MarginalizationFactor evaluates r_p + J_p dx with dx = x - x0 in the tangent space (poses: [p - p0,
// Log(q0^-1 q)]), with the kept blocks at their current addresses.
#pragma once

#include <memory>
#include <set>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/loss_function.h>
#include <Eigen/Core>

namespace vigil::estimator {

// One residual block to marginalize (the caller keeps the cost and loss functions alive during Marginalize).
struct MarginalizationTerm {
  const ceres::CostFunction* cost = nullptr;
  const ceres::LossFunction* loss = nullptr;  // may be null
  std::vector<double*> blocks;
};

struct LinearPrior {
  struct Block {
    double* address = nullptr;
    int size = 0;     // ambient size (7: pose)
    int tangent = 0;  // tangent size
    std::vector<double> x0;
  };
  std::vector<Block> blocks;
  Eigen::MatrixXd J;  // rows x sum of tangent sizes
  Eigen::VectorXd r;

  bool Involves(const double* address) const;
};

// Returns false when nothing is left to keep or the numbers are not finite.
bool Marginalize(const std::vector<MarginalizationTerm>& terms, const std::set<const double*>& dropped,
                 double eigen_threshold, LinearPrior* prior);

class MarginalizationFactor : public ceres::CostFunction {
 public:
  explicit MarginalizationFactor(std::shared_ptr<const LinearPrior> prior);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;
  std::vector<double*> parameter_blocks() const;

 private:
  std::shared_ptr<const LinearPrior> prior_;
};

}  // namespace vigil::estimator
