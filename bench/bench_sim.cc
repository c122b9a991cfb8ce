// Simulator throughput: the paper's 20 s scenario (4001 IMU samples, 601 frames, 36 landmarks).
//   build/bench/bench_sim --benchmark_filter=Paper
#include <benchmark/benchmark.h>

#include "sim/simulator.h"

namespace {

vigil::sim::SimOptions PaperOptions(bool glitches) {
  vigil::sim::SimOptions o;  // the defaults are configs/paper.yaml's scenario
  o.glitch.enabled = glitches;
  o.glitch.mean = 50.0;
  o.glitch.std = 10.0;
  return o;
}

void BM_SimulatePaper(benchmark::State& state) {
  const vigil::sim::SimOptions options = PaperOptions(state.range(0) != 0);
  uint64_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(vigil::sim::Simulate(options, seed++));
}
BENCHMARK(BM_SimulatePaper)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_SimulateRescue(benchmark::State& state) {
  vigil::sim::SimOptions options;
  options.duration_s = 36.0;
  options.trajectory.type = vigil::sim::TrajectoryType::kRescue;
  options.landmarks.layout = vigil::sim::LandmarkLayout::kRandom;
  options.landmarks.random_count = 300;
  uint64_t seed = 1;
  for (auto _ : state) benchmark::DoNotOptimize(vigil::sim::Simulate(options, seed++));
}
BENCHMARK(BM_SimulateRescue)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
