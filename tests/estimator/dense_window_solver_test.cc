// The dense Levenberg-Marquardt against Ceres on the same synthetic window (synthetic_window.h): the same
// cost, a minimum Ceres cannot improve, and the gauge held when there is no prior.
#include "estimator/dense_window_solver.h"

#include <memory>
#include <vector>

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <gtest/gtest.h>

#include "estimator/pose_manifold.h"
#include "tests/estimator/synthetic_window.h"

namespace vigil::estimator {
namespace {

DenseWindowProblem DenseProblemOf(testing::SyntheticWindow& w, bool with_prior) {
  DenseWindowProblem p;
  p.poses = w.pose_blocks;
  p.speed_biases = w.speed_bias_blocks;
  p.prior = with_prior ? &w.prior : nullptr;
  p.hold_oldest_pose = !with_prior;
  p.factors = w.terms;
  for (int i = 0; i < testing::SyntheticWindow::tracks; ++i)
    p.tracks.push_back({&w.inv_depths[i], w.track_terms[i]});
  p.reprojection_loss = &w.loss;
  return p;
}

// The same window as a Ceres problem (the prior as its factors, split by block as the estimator adds them).
struct CeresWindow {
  explicit CeresWindow(testing::SyntheticWindow& w) {
    ceres::Problem::Options options;
    options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    problem = std::make_unique<ceres::Problem>(options);
    for (double* pose : w.pose_blocks) problem->AddParameterBlock(pose, kPoseSize, &manifold);
    for (const MarginalizationTerm& t : w.terms)
      problem->AddResidualBlock(const_cast<ceres::CostFunction*>(t.cost), nullptr,
                                std::vector<double*>(t.blocks.begin(), t.blocks.end()));
    for (const MarginalizationTerm& t : w.reprojection_terms)
      problem->AddResidualBlock(const_cast<ceres::CostFunction*>(t.cost), &w.loss,
                                std::vector<double*>(t.blocks.begin(), t.blocks.end()));
    prior_factors = PriorFactors(std::make_shared<const LinearPrior>(w.prior));
    for (const auto& factor : prior_factors)
      problem->AddResidualBlock(factor.get(), nullptr, factor->parameter_blocks());
  }
  PoseManifold manifold;
  std::unique_ptr<ceres::Problem> problem;
  std::vector<std::unique_ptr<MarginalizationFactor>> prior_factors;
};

TEST(DenseWindowSolver, ItsCostIsCeresCost) {
  testing::SyntheticWindow w(5);
  const DenseWindowProblem dense = DenseProblemOf(w, true);
  double cost = 0.0;
  ASSERT_TRUE(DenseWindowCost(dense, &cost));
  CeresWindow ceres_window(w);
  double expected = 0.0;
  ASSERT_TRUE(ceres_window.problem->Evaluate(ceres::Problem::EvaluateOptions(), &expected, nullptr, nullptr,
                                             nullptr));
  EXPECT_GT(cost, 1.0);
  EXPECT_NEAR(cost, expected, 1e-12 * expected);
}

// Step for step what Ceres' Levenberg-Marquardt does on the same window with the dense solver's initial
// damping: the same damped steps (the depths damped too), the same acceptance and trust-region updates.
TEST(DenseWindowSolver, TakesTheStepsOfCeresLevenbergMarquardt) {
  for (const int iterations : {1, 6, 20}) {
    testing::SyntheticWindow mine(5), reference(5);
    const DenseSolveSummary summary = SolveDenseWindow(
        DenseProblemOf(mine, true), DenseSolveOptions{iterations, 0, 0.0, 0.0}, PoseManifold());
    ASSERT_TRUE(summary.usable) << summary.message;
    // The full Gauss-Newton step overshoots on this window: Ceres too rejects the first five steps.
    if (iterations <= 6) {
      EXPECT_EQ(summary.successful_steps, iterations == 1 ? 0 : 1);
    }
    EXPECT_EQ(summary.successful_steps + summary.unsuccessful_steps, iterations);

    CeresWindow ceres_window(reference);
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    options.initial_trust_region_radius = 1e8;
    options.jacobi_scaling = false;
    options.max_num_iterations = iterations;
    options.function_tolerance = 0.0;
    options.gradient_tolerance = 0.0;
    options.parameter_tolerance = 0.0;
    ceres::Solver::Summary ceres_summary;
    ceres::Solve(options, ceres_window.problem.get(), &ceres_summary);
    ASSERT_TRUE(ceres_summary.IsSolutionUsable());
    EXPECT_NEAR(summary.final_cost, ceres_summary.final_cost, 1e-8 * ceres_summary.final_cost) << iterations;
    for (int k = 0; k < testing::SyntheticWindow::frames; ++k) {
      for (int i = 0; i < kPoseSize; ++i) EXPECT_NEAR(mine.poses[k][i], reference.poses[k][i], 1e-8) << k;
      for (int i = 0; i < kSpeedBiasSize; ++i)
        EXPECT_NEAR(mine.speed_biases[k][i], reference.speed_biases[k][i], 1e-8) << k;
    }
    for (int i = 0; i < testing::SyntheticWindow::tracks; ++i)
      EXPECT_NEAR(mine.inv_depths[i], reference.inv_depths[i], 1e-8) << i;
  }
}

TEST(DenseWindowSolver, HoldsTheOldestPoseWithoutAPrior) {
  testing::SyntheticWindow w(7);
  const std::vector<double> oldest = w.poses[0], newest = w.poses[2];
  const DenseSolveSummary summary =
      SolveDenseWindow(DenseProblemOf(w, false), DenseSolveOptions{20, 0, 1e-12, 0.0}, PoseManifold());
  ASSERT_TRUE(summary.usable) << summary.message;
  EXPECT_GT(summary.successful_steps, 0);
  EXPECT_EQ(w.poses[0], oldest);
  EXPECT_NE(w.poses[2], newest);
}

TEST(DenseWindowSolver, StopsAtMaxIterations) {
  testing::SyntheticWindow w(5);
  const DenseSolveSummary summary =
      SolveDenseWindow(DenseProblemOf(w, true), DenseSolveOptions{2, 0, 0.0, 0.0}, PoseManifold());
  EXPECT_EQ(summary.successful_steps + summary.unsuccessful_steps, 2);
}

}  // namespace
}  // namespace vigil::estimator
