// Estimator cost and accuracy on the paper's scenario (ellipse, 36 landmarks, IMU 200 Hz, camera 30 Hz).
//   build/bench/bench_estimator                      whole 20 s and 200 s runs, per-frame
//   optimize/marginalize build/bench/bench_estimator --accuracy [seeds]   ATE RMSE (posyaw) per seed:
//   nominal, and N(50,10) glitches
//                                                    on az at rate 0.01 without a detector
// The simulation is outside the timed region; counters give per-frame costs in ms and the ATE in m.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <benchmark/benchmark.h>

#include "estimator/run_estimator.h"
#include "tests/estimator/sim_run.h"

namespace {

using vigil::estimator::EstimatorInput;
using vigil::estimator::EstimatorOptions;
using vigil::estimator::EstimatorResult;

vigil::sim::SimOptions PaperOptions(double duration_s, bool glitches) {
  vigil::sim::SimOptions o;  // the defaults are configs/paper.yaml's scenario
  o.duration_s = duration_s;
  o.glitch.enabled = glitches;
  o.glitch.mean = 50.0;
  o.glitch.std = 10.0;
  o.glitch.rate = 0.01;
  return o;
}

void BM_RunPaper(benchmark::State& state) {
  const vigil::sim::SimOptions options = PaperOptions(static_cast<double>(state.range(0)), false);
  const vigil::Dataset data = vigil::sim::Simulate(options, 1);
  const EstimatorInput input = vigil::estimator::testing::InputFromSimulation(options, data, 1);
  EstimatorResult result;
  for (auto _ : state) result = vigil::estimator::RunEstimator(EstimatorOptions{}, input);
  const double frames = result.frames;
  state.counters["frames"] = frames;
  state.counters["optimize_ms_per_frame"] = 1e3 * result.timing.optimize_s / frames;
  state.counters["marginalize_ms_per_frame"] = 1e3 * result.timing.marginalize_s / frames;
  state.counters["ate_m"] = vigil::estimator::testing::PosYawAteRmse(result.states, data.groundtruth);
  state.counters["ok"] = result.ok ? 1.0 : 0.0;
}
BENCHMARK(BM_RunPaper)->Arg(20)->Arg(200)->Unit(benchmark::kMillisecond)->Iterations(1);

int Accuracy(int seeds) {
  for (const bool glitches : {false, true}) {
    double sum = 0.0, worst = 0.0;
    for (int seed = 1; seed <= seeds; ++seed) {
      const vigil::sim::SimOptions options = PaperOptions(20.0, glitches);
      const vigil::Dataset data = vigil::sim::Simulate(options, static_cast<uint64_t>(seed));
      const EstimatorResult result = vigil::estimator::RunEstimator(
          EstimatorOptions{}, vigil::estimator::testing::InputFromSimulation(options, data, seed));
      const double ate = vigil::estimator::testing::PosYawAteRmse(result.states, data.groundtruth);
      std::printf(
          "%s seed %d: ok %d ate_rmse_m %.4f frames_out %zu keyframes %d optimize_s %.3f marginalize_s "
          "%.3f%s%s\n",
          glitches ? "glitch N(50,10) az" : "nominal", seed, result.ok ? 1 : 0, ate, result.states.size(),
          result.keyframes, result.timing.optimize_s, result.timing.marginalize_s,
          result.ok ? "" : " reason: ", result.failure_reason.c_str());
      sum += ate;
      worst = std::max(worst, ate);
    }
    std::printf("%s: mean %.4f m, worst %.4f m over %d seeds\n", glitches ? "glitch" : "nominal", sum / seeds,
                worst, seeds);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "--accuracy") == 0)
    return Accuracy(argc >= 3 ? std::atoi(argv[2]) : 5);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
