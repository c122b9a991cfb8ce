// Rendering speed of the figures of a synthetic paper-sized sweep: 3 glitch settings x 3 methods x 10 seeds,
// 20 s trajectories (the target: all figures in under 10 s). The sweep is written once into a temporary
// directory before timing; each iteration loads it and renders the six 1600 x 1000 figures.
#include <unistd.h>

#include <filesystem>

#include <benchmark/benchmark.h>

#include "plots/render.h"
#include "tests/plots/synthetic_runs.h"

namespace {

const std::filesystem::path& SweepDir() {
  static const std::filesystem::path dir = [] {
    const auto path =
        std::filesystem::temp_directory_path() / ("vigil_bench_plots_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path);
    vigil::plots::testing::WriteSyntheticSweep(path, {{true, 1.0, 0.5}, {true, 2.0, 1.0}, {true, 4.0, 2.0}},
                                               10, 20.0);
    return path;
  }();
  return dir;
}

void BM_RenderPaperSweepFigures(benchmark::State& state) {
  const vigil::plots::FigureOptions options;
  for (auto _ : state) {
    benchmark::DoNotOptimize(vigil::plots::RenderSweepFigures(SweepDir(), options));
  }
  std::filesystem::remove_all(SweepDir());
}
BENCHMARK(BM_RenderPaperSweepFigures)->Unit(benchmark::kSecond)->Iterations(3)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
