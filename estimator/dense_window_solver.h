// A Levenberg-Marquardt solve built for the window (SolverOptions::backend: dense).
//
// Once every feature's inverse depth is eliminated, the window is small and dense: 15 numbers per frame
// (pose tangent and speed-bias), 240 for a window of 16 frames, and 3 per landmark point when the window
// keeps them (window.oldest_tracks points). Each iteration linearizes it in the fixed layout of
// WindowInformation (a track's reprojections and its depth's Schur complement in fixed sizes, no index
// maps), solves the damped normal equations by a dense Cholesky factorization, recovers each depth's
// step from its eliminated row, and accepts the step when the cost falls. A Ceres solve of the same window
// spends most of its time in generic machinery (its evaluator, the block-sparse Schur eliminator of dynamic
// sizes, the manifold products).
//
// The cost is Ceres': 1/2 sum rho(|r|^2) over the factors, the reprojections with their robust loss, and
// 1/2 |r + J dx|^2 for a marginalization prior. The stopping rules are those of the Ceres solve the estimator
// runs (estimator_options.h, SolverOptions): at most max_iterations steps (accepted or not), an end after
// accepted_steps accepted steps once the cost is within the noise model's expectation (half the number of
// residuals), an end when a step changes the cost by less than function_tolerance of it, and the optional
// wall-clock limit.
#pragma once

#include <string>
#include <vector>

#include <ceres/loss_function.h>
#include <ceres/manifold.h>

#include "estimator/marginalization.h"
#include "estimator/window_information.h"

namespace vigil::estimator {

// The window's factors over its blocks: frame k's pose (ambient kPoseSize, tangent kPoseTangentSize) and
// speed-bias blocks. The caller keeps every cost, loss and block alive during the solve.
struct DenseWindowProblem {
  std::vector<double*> poses;
  std::vector<double*> speed_biases;
  std::vector<double*> points;         // landmark points in W (window.oldest_tracks points), 3 doubles each
  bool hold_oldest_pose = false;       // the gauge, when there is no prior: frame 0's pose stays
  const LinearPrior* prior = nullptr;  // may be null
  std::vector<MarginalizationTerm> factors;  // over window blocks only (the points' factors included)
  struct Track {
    double* inv_depth = nullptr;
    std::vector<WindowInformation::Reprojection> reprojections;  // all over inv_depth
  };
  std::vector<Track> tracks;
  const ceres::LossFunction* reprojection_loss = nullptr;
  double eigen_threshold = 1e-8;  // a depth pivot at or below it carries no information (AddTrack)
};

struct DenseSolveOptions {
  int max_iterations = 8;
  int accepted_steps = 1;
  double function_tolerance = 1e-3;
  double max_time_s = 0.0;  // wall-clock limit (0: none), checked after each step
};

struct DenseSolveSummary {
  bool usable = false;  // the states hold a solution (the initial one when no step was accepted)
  int successful_steps = 0;
  int unsuccessful_steps = 0;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  std::string message;  // why it failed, when it did
};

// Solves in place; `pose_manifold` moves the poses along a tangent step.
DenseSolveSummary SolveDenseWindow(const DenseWindowProblem& problem, const DenseSolveOptions& options,
                                   const ceres::Manifold& pose_manifold);

// The problem's cost at the blocks' current values; false when a factor fails or the cost is not finite.
bool DenseWindowCost(const DenseWindowProblem& problem, double* cost);

}  // namespace vigil::estimator
