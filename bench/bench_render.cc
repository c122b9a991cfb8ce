// Rendering cost of the simulator's camera images (sim/image_renderer.h) per 640 x 480 frame of the paper's
// ellipse, and the PNG encoding of a frame (zlib level 1, 3, 6; counter png_bytes). Report min / median over
// repetitions:
//   build/bench/bench_render --benchmark_repetitions=5 --benchmark_report_aggregates_only=false
// Args: exposure (0: sharp, 1: motion blur with images.blur_samples sub-frames), antialias samples,
// distortion (0/1).
#include <benchmark/benchmark.h>

#include <memory>

#include "sim/image_renderer.h"
#include "sim/scene.h"
#include "sim/trajectory_model.h"

namespace {

vigil::CameraModel Vga(bool distorted) {
  vigil::CameraModel cam;
  cam.width = 640;
  cam.height = 480;
  cam.cx = 319.5;
  cam.cy = 239.5;
  if (distorted) cam.distortion = {-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05};
  return cam;
}

void BM_RenderFrame(benchmark::State& state) {
  vigil::sim::ImageOptions options;
  options.exposure_s = state.range(0) ? 0.01 : 0.0;
  options.antialias_samples = static_cast<int>(state.range(1));
  const vigil::CameraModel cam = Vga(state.range(2) != 0);
  const std::unique_ptr<vigil::sim::TrajectoryModel> motion =
      vigil::sim::MakeTrajectoryModel(vigil::sim::TrajectoryOptions{});
  vigil::sim::ImageRenderer renderer(vigil::sim::MakeHouseScene(), cam, options, 1);
  int k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(renderer.Render(*motion, (k % 600) / 30.0, 20.0, k));
    ++k;
  }
}
BENCHMARK(BM_RenderFrame)
    ->ArgNames({"blur", "msaa", "distort"})
    ->Args({0, 4, 0})
    ->Args({1, 4, 0})
    ->Args({0, 0, 0})
    ->Args({0, 4, 1})
    ->Unit(benchmark::kMillisecond);

void BM_EncodePng(benchmark::State& state) {
  const vigil::CameraModel cam = Vga(false);
  const std::unique_ptr<vigil::sim::TrajectoryModel> motion =
      vigil::sim::MakeTrajectoryModel(vigil::sim::TrajectoryOptions{});
  vigil::sim::ImageRenderer renderer(vigil::sim::MakeHouseScene(), cam, vigil::sim::ImageOptions{}, 1);
  const std::vector<uint8_t> gray = renderer.Render(*motion, 2.0, 20.0, 0);
  std::size_t bytes = 0;
  for (auto _ : state)
    bytes = vigil::sim::EncodeGrayPng(gray, cam.width, cam.height, static_cast<int>(state.range(0))).size();
  state.counters["png_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_EncodePng)->ArgName("compression")->Arg(1)->Arg(3)->Arg(6)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
