// The window's solve by the dense Levenberg-Marquardt (SolverOptions::backend: dense): the factors Optimize
// gives Ceres, over the frames' own blocks, and the same IMU gating, gauge and failure reasons.
#include <memory>
#include <vector>

#include "estimator/dense_window_solver.h"
#include "estimator/estimator.h"

namespace vigil::estimator {

bool Estimator::OptimizeDense(bool marginalize_oldest_next, std::string* reason) {
  RepropagateImuFactors();
  DenseWindowProblem problem;
  for (const auto& f : window_) {
    problem.poses.push_back(f->pose);
    problem.speed_biases.push_back(f->speed_bias);
  }
  // Without a prior the window's gauge (position and yaw) is free: hold the oldest pose.
  problem.hold_oldest_pose = !prior_;
  problem.prior = prior_.get();
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  if (bias_prior_) problem.factors.push_back({bias_prior_.get(), nullptr, {problem.speed_biases.front()}});
  std::vector<ImuTerm> imu_terms;
  AppendImuTerms(problem.speed_biases, &costs, &imu_terms);
  for (const ImuTerm& term : imu_terms)
    problem.factors.push_back({term.factor, nullptr, {term.blocks.begin(), term.blocks.end()}});
  AppendZeroVelocityTerms(problem.speed_biases, &costs, &problem.factors);
  problem.points = PointBlocks();
  AppendPointTerms(&costs, &problem.factors);
  std::vector<ReprojectionTerm> reprojections;
  for (auto& [id, track] : features_.tracks()) {
    if (!IsDepthTrack(id, track)) continue;
    reprojections.clear();
    AppendReprojectionTerms(id, track, &track.inv_depth, &reprojections);
    DenseWindowProblem::Track& t = problem.tracks.emplace_back();
    t.inv_depth = &track.inv_depth;
    for (const ReprojectionTerm& term : reprojections) t.reprojections.push_back({term.factor, term.blocks});
  }
  reprojection_factors_.KeepTracks(features_.tracks());
  problem.reprojection_loss = &loss_;
  problem.eigen_threshold = options_.window.marginalization_eigen_threshold;

  const DenseSolveOptions solve{
      options_.solver.max_iterations, options_.solver.accepted_steps, options_.solver.function_tolerance,
      options_.solver.max_time_s *
          (marginalize_oldest_next ? options_.solver.marginalize_old_time_factor : 1.0)};
  const NavState oldest_before = window_.front()->State();
  DenseSolveSummary summary = SolveDenseWindow(problem, solve, pose_manifold_);
  if (summary.usable && GateImuFactors(options_.mitigation.gating, imu_terms, &gating_) > 0) {
    timing_.solver_iterations += summary.successful_steps + summary.unsuccessful_steps;
    summary = SolveDenseWindow(problem, solve, pose_manifold_);
  }
  timing_.solver_iterations += summary.successful_steps + summary.unsuccessful_steps;
  if (!summary.usable) {
    *reason = "solver failed: " + summary.message;
    return false;
  }
  if (prior_) HoldGauge(oldest_before);
  return true;
}

}  // namespace vigil::estimator
