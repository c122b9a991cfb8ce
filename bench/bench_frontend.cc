// Benchmark of the visual front-end (Google Benchmark; built with the project, not run by CI).
//
//   BM_TrackFrame/<variant>  the cost of FeatureTracker::Track per 640 x 480 image (time per iteration = per
//                            frame), on a seeded synthetic texture seen by a camera moving 4 px, 0.17 deg and
//                            0.2 % of zoom per frame (tracks leave the image and are replaced all the time);
//                            variants: 0 default (VINS-Mono's settings), 1 + backward check, 2 + CLAHE,
//                            3 + EuRoC-like lens distortion, 4 anchor refinement (affine realignment of
//                            every track with its first patch) with a 15 px window and patch, as
//                            configs/paper_images.yaml.
//
// Run on one core: taskset -c 0 build/bench/bench_frontend --benchmark_repetitions=10
//                  --benchmark_report_aggregates_only=true   (then read min and median)
// OpenCV's own thread pool is limited to one thread here, as in a sweep's single-threaded runs.
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>

#include "frontend/feature_tracker.h"
#include "tests/frontend/synthetic_images.h"

namespace vigil::frontend {
namespace {

constexpr int kFrames = 60;
constexpr int64_t kPeriod_ns = 50'000'000;

const std::vector<cv::Mat>& Sequence() {
  static const std::vector<cv::Mat> images = [] {
    testing::PlaneMotion motion;
    motion.translation_px = {4.0, 1.0};
    motion.angle_rad = 0.003;
    motion.scale = 0.002;
    const cv::Mat texture = testing::MakeTexture(1600, 1200, 5);
    return motion.Frames(texture, kFrames);
  }();
  return images;
}

void BM_TrackFrame(benchmark::State& state) {
  cv::setNumThreads(1);
  FeatureTrackerOptions options;
  CameraModel camera;  // 640 x 480, focal length 460 px, principal point (320, 240)
  camera.height = 480;
  camera.cx = 320.0;
  camera.cy = 240.0;
  switch (state.range(0)) {
    case 1:
      options.backward_check = true;
      break;
    case 2:
      options.clahe = true;
      break;
    case 3:
      camera.distortion = {-0.28, 0.074, 0.0002, 0.00002};
      break;
    case 4:
      options.anchor_refinement = true;
      options.klt_window_px = options.anchor_patch_px = 15;
      break;
    default:
      break;
  }
  const std::vector<cv::Mat>& images = Sequence();
  auto tracker = std::make_unique<FeatureTracker>(options, camera);
  int k = 0;
  int64_t features = 0;
  for (auto _ : state) {
    if (k == kFrames) {
      state.PauseTiming();
      tracker = std::make_unique<FeatureTracker>(options, camera);
      k = 0;
      state.ResumeTiming();
    }
    const auto frame = tracker->Track(images[k], k * kPeriod_ns);
    features += static_cast<int64_t>(frame->features.size());
    ++k;
  }
  state.counters["features"] = static_cast<double>(features) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_TrackFrame)->ArgName("variant")->DenseRange(0, 4)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vigil::frontend

BENCHMARK_MAIN();
