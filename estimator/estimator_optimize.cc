// The window's nonlinear least-squares problem and its Ceres solve.
#include <algorithm>
#include <cassert>
#include <memory>
#include <vector>

#include <ceres/iteration_callback.h>
#include <ceres/ordered_groups.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include "core/so3.h"
#include "estimator/estimator.h"
#include "estimator/imu_factor.h"
#include "estimator/imu_gating.h"
#include "estimator/point_reprojection_factor.h"
#include "estimator/zero_velocity_factor.h"

namespace vigil::estimator {
namespace {

// Ends a solve after `steps` accepted steps (EstimatorOptions::solver.accepted_steps) once the window is
// consistent with its noise model: a cost (1/2 the sum of squared whitened residuals) at most its
// expectation, half the number of residuals. A window that is not (a glitch burst in its IMU factors, a
// re-initialization on bad data) keeps iterating up to max_iterations.
class StopAfterAcceptedSteps : public ceres::IterationCallback {
 public:
  StopAfterAcceptedSteps(int steps, int num_residuals) : steps_(steps), expected_cost_(0.5 * num_residuals) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (summary.iteration == 0 || !summary.step_is_successful) return ceres::SOLVER_CONTINUE;
    ++accepted_;
    if (accepted_ >= steps_ && summary.cost <= expected_cost_) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    return ceres::SOLVER_CONTINUE;
  }

 private:
  int steps_;
  double expected_cost_;
  int accepted_ = 0;
};

// Copies of parameter blocks in one array, in the order they are added, written back by CopyBack(). Ceres
// orders the blocks of an elimination group by address, so for copies that order is the order of Add().
class ContiguousCopies {
 public:
  explicit ContiguousCopies(std::size_t total_size) { storage_.reserve(total_size); }
  double* Add(double* block, int size) {
    assert(storage_.size() + size <= storage_.capacity());  // the copies never move
    double* copy = storage_.data() + storage_.size();
    storage_.insert(storage_.end(), block, block + size);
    copies_.push_back({block, copy, size});
    return copy;
  }
  void CopyBack() const {
    for (const Copy& c : copies_) std::copy_n(c.copy, c.size, c.original);
  }

 private:
  struct Copy {
    double* original;
    const double* copy;
    int size;
  };
  std::vector<double> storage_;
  std::vector<Copy> copies_;
};

ceres::Problem::Options WindowProblemOptions() {
  ceres::Problem::Options options;
  options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  options.enable_fast_removal = false;
  // The problem is rebuilt every frame by Optimize, always from the window's own blocks (distinct,
  // non-overlapping arrays of fixed sizes), so Ceres' per-block checks against aliasing and size mismatches
  // find nothing; they cost 1.1 % of a paper run's instructions (callgrind, BM_RunPaper/20).
  options.disable_all_safety_checks = true;
  return options;
}

ceres::Solver::Options WindowSolverOptions(const SolverOptions& solver, bool marginalize_oldest_next,
                                           std::shared_ptr<ceres::ParameterBlockOrdering> ordering) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_SCHUR;
  options.trust_region_strategy_type = ceres::DOGLEG;
  options.max_num_iterations = solver.max_iterations;

  options.function_tolerance = solver.function_tolerance;
  options.num_threads = 1;
  options.linear_solver_ordering = std::move(ordering);
  // Every residual is whitened (IMU: square-root information, reprojection: focal length / pixel std, prior:
  // square-root form), so the columns need no Jacobi rescaling; skipping it saves two passes over the
  // Jacobian per iteration (about 4 % of a run) and leaves the ATE unchanged (seeds 1-5, 4 decimals).
  options.jacobi_scaling = false;
  options.logging_type = ceres::SILENT;
  if (solver.max_time_s > 0.0)
    options.max_solver_time_in_seconds =
        solver.max_time_s * (marginalize_oldest_next ? solver.marginalize_old_time_factor : 1.0);
  return options;
}

}  // namespace

// Ceres eliminates the first group of the ordering (DENSE_SCHUR's Schur complement) and orders the blocks of
// a group by address. Group 0 holds every inverse depth and the speed-bias blocks of alternate frames outside
// the prior: an independent set, since a speed-bias block couples only to its neighbours' states (eliminating
// them keeps the reduced camera matrix about a quarter smaller). Those blocks are solved as ContiguousCopies,
// so that their order is the window's and the tracks' and results never depend on heap addresses. Group
// k + 1 holds the rest of frame k (its pose first: the pose precedes the speed-bias block in Frame).
struct Estimator::Elimination {
  std::vector<std::pair<int, FeatureTrack*>> tracks;  // the usable tracks: their inverse depths
  std::vector<bool> speed_bias;                       // per window frame: its speed-bias block
  std::size_t size = 0;                               // doubles in the eliminated blocks
};

// The window's problem and what its solve and write-back need.
struct Estimator::WindowProblem {
  explicit WindowProblem(std::size_t eliminated_size)
      : problem(WindowProblemOptions()), eliminated(eliminated_size) {}
  ceres::Problem problem;
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;  // the factors built for this solve
  ContiguousCopies eliminated;
  std::shared_ptr<ceres::ParameterBlockOrdering> ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  std::vector<double*> speed_bias;  // per window frame: its block or the eliminated copy
  std::vector<double*> inv_depth;   // per Elimination::tracks entry: the eliminated copy
  std::vector<ImuTerm> imu_terms;   // for gating
};

bool Estimator::Optimize(bool marginalize_oldest_next, std::string* reason) {
  RepropagateImuFactors();
  const Elimination elimination = PlanElimination();
  WindowProblem window(elimination.size);
  AddStateBlocks(elimination, &window);
  AddPriors(&window);
  AddImuFactors(&window);
  AddZeroVelocityFactors(&window);
  AddReprojectionFactors(elimination, &window);
  AddPointFactors(&window);
  const NavState oldest_before = window_.front()->State();
  const ceres::Solver::Summary summary =
      SolveAndGate(WindowSolverOptions(options_.solver, marginalize_oldest_next, window.ordering), &window);
  window.eliminated.CopyBack();
  if (!summary.IsSolutionUsable()) {
    *reason = "solver failed: " + summary.message;
    return false;
  }
  if (prior_) HoldGauge(oldest_before);
  return true;
}

// Re-integrates the IMU factors whose bias estimate moved far from their linearization point.
void Estimator::RepropagateImuFactors() {
  for (std::size_t i = 1; i < window_.size(); ++i) {
    const NavState s = window_[i - 1]->State();
    Preintegration& pre = *window_[i]->imu_from_prev;
    if ((s.b_a - pre.linearized_b_a()).norm() > options_.window.repropagate_accel_bias ||
        (s.b_g - pre.linearized_b_g()).norm() > options_.window.repropagate_gyro_bias)
      pre.Repropagate(s.b_a, s.b_g);
  }
}

Estimator::Elimination Estimator::PlanElimination() {
  Elimination e;
  for (auto& [id, track] : features_.tracks())
    if (IsDepthTrack(id, track)) e.tracks.emplace_back(id, &track);
  e.speed_bias.resize(window_.size());
  e.size = e.tracks.size();
  for (std::size_t k = 0; k < window_.size(); ++k) {
    e.speed_bias[k] =
        (k == 0 || !e.speed_bias[k - 1]) && !(prior_ && prior_->Involves(window_[k]->speed_bias));
    if (e.speed_bias[k]) e.size += kSpeedBiasSize;
  }
  return e;
}

void Estimator::AddStateBlocks(const Elimination& elimination, WindowProblem* w) {
  for (std::size_t k = 0; k < window_.size(); ++k)
    w->speed_bias.push_back(elimination.speed_bias[k]
                                ? w->eliminated.Add(window_[k]->speed_bias, kSpeedBiasSize)
                                : window_[k]->speed_bias);
  for (const auto& [id, track] : elimination.tracks)
    w->inv_depth.push_back(w->eliminated.Add(&track->inv_depth, 1));
  for (std::size_t k = 0; k < window_.size(); ++k) {
    w->problem.AddParameterBlock(window_[k]->pose, kPoseSize, &pose_manifold_);
    w->problem.AddParameterBlock(w->speed_bias[k], kSpeedBiasSize);
    w->ordering->AddElementToGroup(window_[k]->pose, static_cast<int>(k) + 1);
    w->ordering->AddElementToGroup(w->speed_bias[k], elimination.speed_bias[k] ? 0 : static_cast<int>(k) + 1);
  }
  for (double* inv_depth : w->inv_depth) w->ordering->AddElementToGroup(inv_depth, 0);
}

void Estimator::AddPriors(WindowProblem* w) {
  // Without a prior the window's gauge (position and yaw) is free: hold the oldest pose.
  if (!prior_) {
    w->problem.SetParameterBlockConstant(window_.front()->pose);
  } else {
    for (auto& factor : PriorFactors(prior_)) {
      w->problem.AddResidualBlock(factor.get(), nullptr, factor->parameter_blocks());
      w->costs.push_back(std::move(factor));
    }
  }
  // A bias-only prior: it does not fix the gauge, so it is independent of the branch above.
  if (bias_prior_) w->problem.AddResidualBlock(bias_prior_.get(), nullptr, w->speed_bias.front());
}

void Estimator::AppendImuTerms(const std::vector<double*>& speed_bias,
                               std::vector<std::unique_ptr<ceres::CostFunction>>* costs,
                               std::vector<ImuTerm>* imu_terms) {
  for (std::size_t k = 1; k < window_.size(); ++k) {
    auto factor = std::make_unique<ImuFactor>(*window_[k]->imu_from_prev, g_W_);
    imu_terms->push_back(
        ImuTerm{factor.get(), {window_[k - 1]->pose, speed_bias[k - 1], window_[k]->pose, speed_bias[k]}});
    costs->push_back(std::move(factor));
  }
}

void Estimator::AppendZeroVelocityTerms(const std::vector<double*>& speed_bias,
                                        std::vector<std::unique_ptr<ceres::CostFunction>>* costs,
                                        std::vector<MarginalizationTerm>* terms) {
  if (!ZeroVelocityActive()) return;
  const ZeroVelocityOptions& o = options_.zero_velocity;
  std::vector<bool> still(window_.size(), false);
  for (std::size_t k = 1; k < window_.size(); ++k) {
    if (!window_[k]->stationary) continue;
    still[k - 1] = still[k] = true;
    auto factor = std::make_unique<NoMotionFactor>(o.position_std_m, o.rotation_std_rad);
    terms->push_back({factor.get(), nullptr, {window_[k - 1]->pose, window_[k]->pose}});
    costs->push_back(std::move(factor));
  }
  for (std::size_t k = 0; k < window_.size(); ++k) {
    if (!still[k]) continue;
    auto factor = std::make_unique<ZeroVelocityFactor>(o.velocity_std_mps);
    terms->push_back({factor.get(), nullptr, {speed_bias[k]}});
    costs->push_back(std::move(factor));
  }
}

void Estimator::AddImuFactors(WindowProblem* w) {
  const std::size_t first = w->costs.size();
  AppendImuTerms(w->speed_bias, &w->costs, &w->imu_terms);
  for (std::size_t i = 0; i < w->imu_terms.size(); ++i)
    w->problem.AddResidualBlock(w->costs[first + i].get(), nullptr, w->imu_terms[i].blocks.data(), 4);
}

void Estimator::AddZeroVelocityFactors(WindowProblem* w) {
  const std::size_t first = w->costs.size();
  std::vector<MarginalizationTerm> terms;
  AppendZeroVelocityTerms(w->speed_bias, &w->costs, &terms);
  for (std::size_t i = 0; i < terms.size(); ++i)
    w->problem.AddResidualBlock(w->costs[first + i].get(), nullptr, terms[i].blocks.data(),
                                static_cast<int>(terms[i].blocks.size()));
}

void Estimator::AddReprojectionFactors(const Elimination& elimination, WindowProblem* w) {
  std::vector<ReprojectionTerm> reprojections;
  for (std::size_t i = 0; i < elimination.tracks.size(); ++i)
    AppendReprojectionTerms(elimination.tracks[i].first, *elimination.tracks[i].second, w->inv_depth[i],
                            &reprojections);
  for (const ReprojectionTerm& term : reprojections)
    w->problem.AddResidualBlock(term.factor, &loss_, term.blocks[0], term.blocks[1], term.blocks[2]);
  // Drop the cached factors of tracks that no longer exist.
  reprojection_factors_.KeepTracks(features_.tracks());
}

// The points' blocks after every frame's group (window.oldest_tracks points), and their factors.
void Estimator::AddPointFactors(WindowProblem* w) {
  for (double* point : PointBlocks()) {
    w->problem.AddParameterBlock(point, kPointSize);
    w->ordering->AddElementToGroup(point, static_cast<int>(window_.size()) + 1);
  }
  const std::size_t first = w->costs.size();
  std::vector<MarginalizationTerm> terms;
  AppendPointTerms(&w->costs, &terms);
  for (std::size_t i = 0; i < terms.size(); ++i)
    w->problem.AddResidualBlock(w->costs[first + i].get(), &loss_, terms[i].blocks[0], terms[i].blocks[1]);
}

// Solves; when IMU factors then fail their chi-square gate (in-estimator mitigation), they are inflated and
// the problem is solved once more.
ceres::Solver::Summary Estimator::SolveAndGate(ceres::Solver::Options solver_options, WindowProblem* w) {
  StopAfterAcceptedSteps stop(options_.solver.accepted_steps, w->problem.NumResiduals());
  if (options_.solver.accepted_steps > 0) solver_options.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &w->problem, &summary);
  if (summary.IsSolutionUsable() && GateImuFactors(options_.mitigation.gating, w->imu_terms, &gating_) > 0) {
    timing_.solver_iterations += summary.num_successful_steps + summary.num_unsuccessful_steps;
    StopAfterAcceptedSteps stop_again(options_.solver.accepted_steps, w->problem.NumResiduals());
    if (options_.solver.accepted_steps > 0) solver_options.callbacks = {&stop_again};
    ceres::Solve(solver_options, &w->problem, &summary);
  }
  timing_.solver_iterations += summary.num_successful_steps + summary.num_unsuccessful_steps;
  return summary;
}

// Position and yaw of the window are unobservable; the prior keeps only relative information, so the solver
// may move the whole window along them. Undo that motion: rotate about z and shift every state so that the
// oldest frame keeps its position and yaw from before the solve.
void Estimator::HoldGauge(const NavState& oldest_before) {
  const NavState oldest_after = window_.front()->State();
  const double dyaw =
      YawOf(oldest_before.q_WB.toRotationMatrix()) - YawOf(oldest_after.q_WB.toRotationMatrix());
  const Eigen::Matrix3d R = RotZ(dyaw);
  const Eigen::Quaterniond q(R);
  for (const auto& f : window_) {
    NavState s = f->State();
    s.p_W = R * (s.p_W - oldest_after.p_W) + oldest_before.p_W;
    s.q_WB = (q * s.q_WB).normalized();
    s.v_W = R * s.v_W;
    f->SetState(s);
  }
  for (auto& [id, point] : points_W_) {
    Eigen::Map<Eigen::Vector3d> p_W(point.data());
    p_W = R * (p_W - oldest_after.p_W) + oldest_before.p_W;
  }
}

}  // namespace vigil::estimator
