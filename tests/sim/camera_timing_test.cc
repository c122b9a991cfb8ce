#include "sim/camera_timing.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/dataset.h"
#include "sim/camera_simulator.h"
#include "sim/simulator.h"
#include "sim/trajectory_model.h"

namespace vigil::sim {
namespace {

const std::vector<int64_t> kGrid = CameraFrameTimes(20.0, 0, 20'000'000'000);

TEST(CameraTiming, OffLeavesTheTimesAlone) { EXPECT_EQ(ApplyCameraTiming({}, 20.0, 1, kGrid), kGrid); }

TEST(CameraTiming, DropsKeepTheEndsAndTheOthersTimes) {
  CameraTimingOptions o;
  o.drop_rate = 0.2;
  const std::vector<int64_t> t = ApplyCameraTiming(o, 20.0, 1, kGrid);
  EXPECT_EQ(t.front(), kGrid.front());
  EXPECT_EQ(t.back(), kGrid.back());
  const double dropped = static_cast<double>(kGrid.size() - t.size()) / static_cast<double>(kGrid.size() - 2);
  EXPECT_NEAR(dropped, 0.2, 0.06);
  for (int64_t x : t) EXPECT_TRUE(std::binary_search(kGrid.begin(), kGrid.end(), x));
}

TEST(CameraTiming, JitterIsBoundedAndKeepsTheOrder) {
  CameraTimingOptions o;
  o.jitter_std_s = 0.01;  // 10 ms: many draws reach the +-22.5 ms clip
  const std::vector<int64_t> t = ApplyCameraTiming(o, 20.0, 1, kGrid);
  ASSERT_EQ(t.size(), kGrid.size());
  double sum_sq = 0.0;
  int moved = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double d = static_cast<double>(t[k] - kGrid[k]);
    EXPECT_LE(std::abs(d), 22'500'000.0 + 1.0);
    sum_sq += d * d;
    moved += t[k] != kGrid[k];
    if (k > 0) {
      EXPECT_GT(t[k], t[k - 1]);
    }
  }
  EXPECT_EQ(t.front(), kGrid.front());
  EXPECT_EQ(t.back(), kGrid.back());
  EXPECT_EQ(moved, static_cast<int>(t.size()) - 2);
  EXPECT_NEAR(std::sqrt(sum_sq / static_cast<double>(t.size())) * 1e-9, 0.01, 0.002);
}

// The simulator takes its tracks at the jittered times: each frame shows the scene at its own timestamp.
TEST(CameraTiming, SimulatedTracksAreSeenAtTheFramesOwnTimes) {
  SimOptions o;
  o.duration_s = 4.0;
  o.faults.camera.jitter_std_s = 0.002;
  o.faults.camera.drop_rate = 0.1;
  const Dataset d = Simulate(o, 5);
  const std::unique_ptr<TrajectoryModel> motion = MakeTrajectoryModel(o.trajectory);
  const std::vector<CameraFrame> expected = SimulateFeatureTracksAt(
      *motion, o.camera, d.landmarks,
      [&] {
        std::vector<int64_t> t;
        for (const CameraFrame& f : d.frames) t.push_back(f.t_ns);
        return t;
      }(),
      5);
  ASSERT_EQ(d.frames.size(), expected.size());
  EXPECT_LT(d.frames.size(), CameraFrameTimes(o.camera.rate_hz, 0, SToNs(o.duration_s)).size());
  for (std::size_t k = 0; k < d.frames.size(); ++k) {
    ASSERT_EQ(d.frames[k].features.size(), expected[k].features.size());
    for (std::size_t i = 0; i < expected[k].features.size(); ++i)
      EXPECT_EQ(d.frames[k].features[i].uv_px, expected[k].features[i].uv_px);
  }
}

}  // namespace
}  // namespace vigil::sim
