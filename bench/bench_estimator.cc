// Estimator cost and accuracy on the paper's scenario (ellipse, 36 landmarks, IMU 200 Hz, camera 30 Hz).
//   build/bench/bench_estimator
//       whole 20 s and 200 s runs; counters: per-frame optimize / marginalize cost [ms], ATE [m]; with
//       --benchmark_repetitions=10 also their median and minimum (one run varies by up to 1.8x on a shared
//       machine; docs/development.md, Benchmarks, for instruction counts)
//   build/bench/bench_estimator --accuracy [seeds [estimator.yaml [nominal]]]
//       ATE RMSE (posyaw) per seed, nominal and with N(50,10) glitches on az at rate 0.01, no detector;
//       estimator.yaml holds keys of the `estimator:` section; VIGIL_EST_TRACE=1 prints every 30th state's
//       error
// The simulation is outside the timed region.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/config.h"
#include "core/so3.h"
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
  state.counters["iterations_per_solve"] =
      static_cast<double>(result.timing.solver_iterations) / std::max(1, result.timing.optimizations);
  state.counters["ate_m"] = vigil::estimator::testing::PosYawAteRmse(result.states, data.groundtruth);
  state.counters["ok"] = result.ok ? 1.0 : 0.0;
}
BENCHMARK(BM_RunPaper)
    ->Arg(20)
    ->Arg(200)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->ComputeStatistics("min",
                        [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });

int Accuracy(int seeds, const EstimatorOptions& estimator_options, bool nominal_only) {
  for (const bool glitches : {false, true}) {
    if (glitches && nominal_only) break;
    double sum = 0.0, worst = 0.0;
    for (int seed = 1; seed <= seeds; ++seed) {
      const vigil::sim::SimOptions options = PaperOptions(20.0, glitches);
      const vigil::Dataset data = vigil::sim::Simulate(options, static_cast<uint64_t>(seed));
      const EstimatorResult result = vigil::estimator::RunEstimator(
          estimator_options, vigil::estimator::testing::InputFromSimulation(options, data, seed));
      const double ate = vigil::estimator::testing::PosYawAteRmse(result.states, data.groundtruth);
      std::printf(
          "%s seed %d: ok %d ate_rmse_m %.4f frames_out %zu keyframes %d optimize_s %.3f marginalize_s "
          "%.3f iterations_per_solve %.2f%s%s\n",
          glitches ? "glitch N(50,10) az" : "nominal", seed, result.ok ? 1 : 0, ate, result.states.size(),
          result.keyframes, result.timing.optimize_s, result.timing.marginalize_s,
          static_cast<double>(result.timing.solver_iterations) / std::max(1, result.timing.optimizations),
          result.ok ? "" : " reason: ", result.failure_reason.c_str());
      if (std::getenv("VIGIL_EST_TRACE")) {
        for (std::size_t i = 0; i < result.states.size(); i += 30) {
          vigil::NavState truth;
          vigil::InterpolateNavState(data.groundtruth, result.states[i].t_ns, &truth);
          const auto& s = result.states[i];
          std::printf(
              "  t %.2f dp %.3f %.3f %.3f dyaw_deg %.3f dv %.3f ba_err %.3f bg_err %.4f\n",
              vigil::NsToS(s.t_ns), s.p_W.x() - truth.p_W.x(), s.p_W.y() - truth.p_W.y(),
              s.p_W.z() - truth.p_W.z(),
              (vigil::YawOf(s.q_WB.toRotationMatrix()) - vigil::YawOf(truth.q_WB.toRotationMatrix())) * 57.3,
              (s.v_W - truth.v_W).norm(), (s.b_a - truth.b_a).norm(), (s.b_g - truth.b_g).norm());
        }
      }
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
  if (argc >= 2 && std::strcmp(argv[1], "--accuracy") == 0) {
    EstimatorOptions options;
    if (argc >= 4) vigil::config::LoadFile(argv[3], options);  // the keys of the `estimator:` section
    return Accuracy(argc >= 3 ? std::atoi(argv[2]) : 5, options,
                    argc >= 5 && std::strcmp(argv[4], "nominal") == 0);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
