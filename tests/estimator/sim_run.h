// Test/bench helpers: the estimator input of a simulated recording and its ATE, both through the same code a
// `vigil run` uses (experiments::MakeEstimatorInput, evaluation::EvaluateTrajectory with posyaw alignment),
// so the estimator's own accuracy checks measure what the runs report.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/interpolation.h"
#include "estimator/estimator_input.h"
#include "evaluation/evaluate_trajectory.h"
#include "experiments/runs/run_inputs.h"
#include "sim/simulator.h"

namespace vigil::estimator::testing {

inline EstimatorInput InputFromSimulation(const sim::SimOptions& options, const Dataset& data,
                                          uint64_t seed) {
  experiments::RunConfig config;
  config.sim = options;
  config.seed = seed;
  return experiments::MakeEstimatorInput(config, data, data.imu);
}

// The default simulated scenario (sim::SimOptions' defaults: the paper's) for `duration_s`, and the
// estimator's input from it.
struct SimulatedRun {
  Dataset data;
  EstimatorInput input;
};
inline SimulatedRun SimulatePaperRun(double duration_s, uint64_t seed) {
  sim::SimOptions options;
  options.duration_s = duration_s;
  SimulatedRun run;
  run.data = sim::Simulate(options, seed);
  run.input = InputFromSimulation(options, run.data, seed);
  return run;
}

// RMSE of the position error after posyaw alignment of `estimate` onto the ground truth interpolated at the
// estimate's times; NaN when nothing is estimated inside the ground truth's span.
inline double PosYawAteRmse(const std::vector<NavState>& estimate, const std::vector<NavState>& groundtruth) {
  Trajectory est, gt;
  for (const NavState& s : estimate) {
    NavState truth;
    if (!InterpolateNavState(groundtruth, s.t_ns, &truth)) continue;
    est.push_back({s.t_ns, s.p_W, s.q_WB});
    gt.push_back({truth.t_ns, truth.p_W, truth.q_WB});
  }
  if (est.empty()) return std::nan("");
  return evaluation::EvaluateTrajectory(gt, est, evaluation::EvaluationOptions{}).ate_trans_m.rmse;
}

}  // namespace vigil::estimator::testing
