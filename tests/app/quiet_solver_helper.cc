// A program set up as `vigil` is (app/solver_logging.h) that runs Ceres solves that fail on their first
// evaluation, on the main thread and on a worker thread: Ceres then logs "Terminating: Residual and Jacobian
// evaluation failed." as an error. Prints nothing when glog is quiet; exits 0 when both solves failed.
#include <thread>

#include <ceres/ceres.h>

#include "app/solver_logging.h"

namespace {

// A residual whose evaluation always fails.
struct FailingCost : ceres::SizedCostFunction<1, 1> {
  bool Evaluate(double const* const*, double*, double**) const override { return false; }
};

bool SolveFails() {
  double x = 1.0;
  ceres::Problem problem;
  problem.AddResidualBlock(new FailingCost, nullptr, &x);
  ceres::Solver::Options options;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  return summary.termination_type == ceres::FAILURE;
}

}  // namespace

int main(int, char** argv) {
  vigil::app::InitSolverLogging(argv[0]);
  bool worker_failed = false;
  std::thread worker([&] { worker_failed = SolveFails(); });
  const bool main_failed = SolveFails();
  worker.join();
  return main_failed && worker_failed ? 0 : 1;
}
