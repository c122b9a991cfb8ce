// The estimator's stages, each timed on a fixed window (bench/estimator_stages.h): the window solve, the
// newest pose's covariance and the oldest frame's marginalization, and the two after a keyframe, with the
// oldest frame's terms linearized once for both (as the estimator does) or twice (`_unshared`).
//   build/bench/bench_estimator_stages [--benchmark_repetitions=10]
// Windows: the paper scenario (configs/paper.yaml, seed 1) at 10 s, and the semi-real V1_01 flight
// (configs/euroc_v1_01_semireal.yaml, seed 1) at 20 s, also with its long tracks kept as landmark points
// (window.oldest_tracks points); a window whose recording is absent is skipped with a message. Counters: the
// window's frames, usable tracks and points. Speeds compare as ratios within one run, or as
// instruction counts (docs/development.md, "Benchmarks").
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/estimator_stages.h"
#include "estimator/run_estimator.h"
#include "experiments/runs/run_config.h"
#include "sim/simulator.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

struct Window {
  std::string config;  // under configs/
  std::vector<std::string> overrides;
  double at_s;  // the window after the frame at this time from the first frame
};

const Window kPaper{"paper.yaml", {"seed=1", "glitch.enabled=false", "estimator.solver.max_time_s=0"}, 10.0};
const Window kSemiReal{
    "euroc_v1_01_semireal.yaml", {"seed=1", "duration_s=30", "estimator.solver.max_time_s=0"}, 20.0};
// The same window with the long tracks kept as landmark points.
const Window kSemiRealPoints{
    "euroc_v1_01_semireal.yaml",
    {"seed=1", "duration_s=30", "estimator.solver.max_time_s=0", "estimator.window.oldest_tracks=points"},
    20.0};

// Runs the window's recording up to its time, then calls `stage` with the estimator's stages there.
void OnWindow(benchmark::State& state, const Window& window,
              const std::function<void(EstimatorStages&)>& stage) {
  experiments::RunConfig config;
  Dataset data;
  try {
    config = experiments::LoadRunConfig(std::string(VIGIL_SOURCE_DIR) + "/configs/" + window.config,
                                        window.overrides);
    data = sim::Simulate(config.sim, config.seed);
  } catch (const std::exception& e) {
    state.SkipWithError(("the window's recording is not here: " + std::string(e.what())).c_str());
    return;
  }
  const EstimatorInput input = testing::InputFromSimulation(config.sim, data, config.seed);
  const int64_t at_ns = data.frames.front().t_ns + static_cast<int64_t>(window.at_s * 1e9);
  bool reached = false;
  RunEstimator(config.estimator, input, [&](Estimator& estimator) {
    if (estimator.newest_state().t_ns < at_ns) return true;
    EstimatorStages stages(&estimator);
    state.counters["frames"] = stages.window_frames();
    state.counters["tracks"] = stages.usable_tracks();
    state.counters["points"] = stages.points();
    stage(stages);
    reached = true;
    return false;
  });
  if (!reached) state.SkipWithError("the run ended before the window");
}

void BM_Solve(benchmark::State& state, const Window& window, SolverBackend backend) {
  OnWindow(state, window, [&](EstimatorStages& stages) {
    for (auto _ : state)
      if (!stages.Solve(backend)) state.SkipWithError("the solve failed");
  });
}

void BM_Covariance(benchmark::State& state, const Window& window) {
  OnWindow(state, window, [&](EstimatorStages& stages) {
    for (auto _ : state)
      if (!stages.Covariance()) state.SkipWithError("no covariance");
  });
}

void BM_CovarianceAndMarginalize(benchmark::State& state, const Window& window, bool shared) {
  OnWindow(state, window, [&](EstimatorStages& stages) {
    for (auto _ : state)
      if (!stages.CovarianceAndMarginalize(shared)) state.SkipWithError("no covariance or prior");
  });
}

void BM_Marginalize(benchmark::State& state, const Window& window, bool general) {
  OnWindow(state, window, [&](EstimatorStages& stages) {
    for (auto _ : state)
      if (!stages.MarginalizeOldest(general)) state.SkipWithError("the marginalization failed");
  });
}

BENCHMARK_CAPTURE(BM_Solve, paper_dense, kPaper, SolverBackend::kDense)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, paper_ceres, kPaper, SolverBackend::kCeres)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Covariance, paper, kPaper)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Marginalize, paper, kPaper, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Marginalize, paper_general, kPaper, true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CovarianceAndMarginalize, paper, kPaper, true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CovarianceAndMarginalize, paper_unshared, kPaper, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, semireal_dense, kSemiReal, SolverBackend::kDense)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, semireal_ceres, kSemiReal, SolverBackend::kCeres)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Covariance, semireal, kSemiReal)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Marginalize, semireal, kSemiReal, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Marginalize, semireal_general, kSemiReal, true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CovarianceAndMarginalize, semireal, kSemiReal, true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CovarianceAndMarginalize, semireal_unshared, kSemiReal, false)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Solve, semireal_points_dense, kSemiRealPoints, SolverBackend::kDense)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Covariance, semireal_points, kSemiRealPoints)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Marginalize, semireal_points, kSemiRealPoints, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Marginalize, semireal_points_general, kSemiRealPoints, true)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CovarianceAndMarginalize, semireal_points, kSemiRealPoints, true)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_CovarianceAndMarginalize, semireal_points_unshared, kSemiRealPoints, false)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace vigil::estimator

BENCHMARK_MAIN();
