// Benchmarks of the glitch detectors (Google Benchmark; built with the project, not run by CI).
//
//   BM_DtwReference/k/N/M/d  one slice against all k templates: straightforward scalar Algorithm 1 in double
//   BM_DtwDetect/k/N/M/d     the production path (DtwMatcher::Best: float, templates in SIMD lanes)
//   BM_Stream<Detector>      whole-stream throughput of each detector (items/s = samples per second)
//
// Run: build/bench/bench_detectors --benchmark_min_time=0.2
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/random.h"
#include "detectors/detector.h"
#include "detectors/dtw_distance.h"
#include "detectors/dtw_matcher.h"
#include "detectors/template_library.h"
#include "detectors/threshold_detector.h"

namespace vigil::detectors {
namespace {

std::vector<double> RandomValues(std::size_t n, uint64_t seed) {
  Rng rng(seed, "bench");
  std::vector<double> v(n);
  for (double& x : v) x = rng.Normal();
  return v;
}

void DtwArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"k", "N", "M", "d"});
  b->Args({10, 40, 40, 3});
  b->Args({10, 10, 40, 6});
}

void BM_DtwReference(benchmark::State& state) {
  const int k = state.range(0), n = state.range(1), m = state.range(2), d = state.range(3);
  const std::vector<double> templates = RandomValues(static_cast<std::size_t>(k) * n * d, 1);
  const std::vector<double> slice = RandomValues(static_cast<std::size_t>(m) * d, 2);
  std::vector<double> row(m + 1);
  for (auto _ : state) {
    double best = std::numeric_limits<double>::infinity();
    for (int t = 0; t < k; ++t)
      best = std::min(best, DtwDistance(templates.data() + static_cast<std::size_t>(t) * n * d, n,
                                        slice.data(), m, d, row.data()));
    benchmark::DoNotOptimize(best);
  }
  state.counters["cells"] = static_cast<double>(k) * n * m;
  state.counters["ns_per_cell"] =
      benchmark::Counter(static_cast<double>(k) * n * m * state.iterations(),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_DtwReference)->Apply(DtwArgs)->Unit(benchmark::kMicrosecond);

void BM_DtwDetect(benchmark::State& state) {
  const int k = state.range(0), n = state.range(1), m = state.range(2), d = state.range(3);
  const std::vector<double> templates = RandomValues(static_cast<std::size_t>(k) * n * d, 1);
  const std::vector<double> slice = RandomValues(static_cast<std::size_t>(m) * d, 2);
  std::vector<float> slice_f(slice.begin(), slice.end());
  DtwMatcher matcher(templates.data(), k, n, d);
  for (auto _ : state) {
    const DtwMatch best = matcher.Best(slice_f.data(), m);
    benchmark::DoNotOptimize(best);
  }
  state.SetLabel(DtwMatcher::KernelName());
  state.counters["ns_per_cell"] =
      benchmark::Counter(static_cast<double>(k) * n * m * state.iterations(),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_DtwDetect)->Apply(DtwArgs)->Unit(benchmark::kMicrosecond);

// A 20 s, 200 Hz stream like the paper's: gravity plus a 0.5 Hz vertical oscillation, white noise, 1 %
// spikes.
ImuStream BenchStream(uint64_t seed, int samples) {
  Rng rng(seed, "bench_stream");
  ImuStream imu(samples);
  for (int t = 0; t < samples; ++t) {
    const double time_s = t / 200.0;
    imu[t].t_ns = static_cast<int64_t>(t) * 5000000;
    imu[t].w_B = {0.1 * std::sin(time_s) + 0.21 * rng.Normal(), 0.2 * std::cos(time_s) + 0.21 * rng.Normal(),
                  0.157 + 0.21 * rng.Normal()};
    imu[t].a_B = {0.5 * std::cos(0.3 * time_s) + 0.27 * rng.Normal(), 0.27 * rng.Normal(),
                  9.81 + 9.87 * std::sin(3.14159 * time_s) + 0.27 * rng.Normal()};
  }
  return imu;
}

void StreamBenchmark(benchmark::State& state, DetectorType type) {
  const ImuStream clean = BenchStream(1000, 4001);
  ImuStream raw = BenchStream(1, 4001);
  Rng glitch(1, "glitch");
  for (ImuSample& s : raw)
    if (glitch.Bernoulli(0.01)) s.a_B.z() += glitch.Normal(50.0, 10.0);
  DetectorOptions options;
  options.type = type;
  options.threshold = WithBounds(options.threshold, CalibrateThresholdBounds(clean, options.threshold));
  const TemplateLibrary library = BuildTemplates(clean, options.dtw);
  for (auto _ : state) {
    const DetectionResult result = DetectAndMitigate(options, raw, &library);
    benchmark::DoNotOptimize(result.flagged.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(raw.size()));
}
void BM_StreamThreshold(benchmark::State& state) { StreamBenchmark(state, DetectorType::kThreshold); }
void BM_StreamRelativeThreshold(benchmark::State& state) {
  StreamBenchmark(state, DetectorType::kRelativeThreshold);
}
void BM_StreamDtw(benchmark::State& state) { StreamBenchmark(state, DetectorType::kDtw); }
void BM_StreamHampel(benchmark::State& state) { StreamBenchmark(state, DetectorType::kHampel); }
BENCHMARK(BM_StreamThreshold)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StreamRelativeThreshold)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StreamDtw)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StreamHampel)->Unit(benchmark::kMicrosecond);

void BM_BuildTemplates(benchmark::State& state) {
  const ImuStream clean = BenchStream(1000, 4001);
  const DtwOptions options;
  for (auto _ : state) {
    const TemplateLibrary library = BuildTemplates(clean, options);
    benchmark::DoNotOptimize(library.threshold);
  }
}
BENCHMARK(BM_BuildTemplates)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vigil::detectors

BENCHMARK_MAIN();
