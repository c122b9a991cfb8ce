#include "sim/camera_simulator.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include <gtest/gtest.h>

#include "sim/ellipse_trajectory.h"
#include "sim/simulator.h"

namespace vigil::sim {
namespace {

// docs/formats.md's projection, written independently of the simulator: (x, y, z) = T_BC^-1 T_WB^-1 p_W.
bool ProjectFromPose(const CameraModel& cam, const Eigen::Quaterniond& q_WB, const Eigen::Vector3d& p_WB,
                     const Eigen::Vector3d& p_W, Eigen::Vector2d* uv) {
  Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
  T_WB.linear() = q_WB.toRotationMatrix();
  T_WB.translation() = p_WB;
  const Eigen::Vector3d p_C = cam.T_BC_iso().inverse() * (T_WB.inverse() * p_W);
  if (p_C.z() <= 0) return false;
  *uv = Eigen::Vector2d(cam.fx * p_C.x() / p_C.z() + cam.cx, cam.fy * p_C.y() / p_C.z() + cam.cy);
  return uv->x() >= 0 && uv->x() < cam.width && uv->y() >= 0 && uv->y() < cam.height;
}

// Without pixel noise every feature is the exact projection of its landmark from the ground-truth pose, and
// every landmark that projects into the image is observed.
TEST(CameraSimulator, FeaturesAreExactProjectionsOfVisibleLandmarks) {
  SimOptions o;
  o.camera.pixel_noise_px = 0.0;
  const Dataset d = Simulate(o, 1);
  std::map<int64_t, const NavState*> truth;
  for (const auto& s : d.groundtruth) truth[s.t_ns] = &s;
  const EllipseTrajectory motion;
  int frames_on_imu_times = 0;
  for (const CameraFrame& f : d.frames) {
    // Pose: the ground-truth row when the frame falls on an IMU sample, else the motion model.
    Eigen::Quaterniond q;
    Eigen::Vector3d p;
    if (auto it = truth.find(f.t_ns); it != truth.end()) {
      q = it->second->q_WB;
      p = it->second->p_W;
      ++frames_on_imu_times;
    } else {
      const TrajectoryState x = motion.StateAt(NsToS(f.t_ns));
      q = x.q_WB;
      p = x.p_W;
    }
    std::vector<int> expected_ids;
    for (const Landmark& l : d.landmarks) {
      Eigen::Vector2d uv;
      if (ProjectFromPose(d.camera, q, p, l.p_W, &uv)) expected_ids.push_back(l.id);
    }
    std::vector<int> ids;
    for (const FeatureObservation& obs : f.features) {
      ids.push_back(obs.id);
      Eigen::Vector2d uv;
      ASSERT_TRUE(ProjectFromPose(d.camera, q, p, d.landmarks[static_cast<std::size_t>(obs.id)].p_W, &uv));
      EXPECT_LT((uv - obs.uv_px).norm(), 1e-9) << "frame " << f.t_ns << " id " << obs.id;
    }
    EXPECT_EQ(ids, expected_ids) << "frame " << f.t_ns;
  }
  EXPECT_EQ(frames_on_imu_times, 201);  // every third frame at 30 Hz falls on the 200 Hz grid
}

TEST(CameraSimulator, FrameTimesFollowTheCameraRate) {
  SimOptions o;
  const Dataset d = Simulate(o, 1);
  ASSERT_EQ(d.frames.size(), 601u);  // t = 0 .. 20 s at 30 Hz, both ends included
  EXPECT_EQ(d.frames[1].t_ns, 33'333'333);
  EXPECT_EQ(d.frames[2].t_ns, 66'666'667);
  EXPECT_EQ(d.frames.back().t_ns, 20'000'000'000);
}

TEST(CameraSimulator, PixelNoiseHasTheConfiguredStd) {
  SimOptions ideal, noisy;
  noisy.camera.pixel_noise_px = 1.5;
  const Dataset a = Simulate(ideal, 4), b = Simulate(noisy, 4);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  double ss = 0;
  int n = 0;
  for (std::size_t i = 0; i < a.frames.size(); ++i) {
    ASSERT_EQ(a.frames[i].features.size(), b.frames[i].features.size());
    for (std::size_t j = 0; j < a.frames[i].features.size(); ++j) {
      ss += (b.frames[i].features[j].uv_px - a.frames[i].features[j].uv_px).squaredNorm();
      n += 2;
    }
  }
  EXPECT_NEAR(std::sqrt(ss / n), 1.5, 0.05);  // about 40000 draws: standard error 0.4%
}

// The paper scenario must keep the house in view: VINS-Mono needs about 20 tracked features per frame.
TEST(CameraSimulator, PaperScenarioSeesTheHouseInEveryFrame) {
  const Dataset d = Simulate(SimOptions(), 1);
  std::size_t lo = 1000, hi = 0, sum = 0;
  for (const CameraFrame& f : d.frames) {
    lo = std::min(lo, f.features.size());
    hi = std::max(hi, f.features.size());
    sum += f.features.size();
  }
  std::printf("features per frame: min %zu mean %.1f max %zu of %zu landmarks\n", lo,
              static_cast<double>(sum) / static_cast<double>(d.frames.size()), hi, d.landmarks.size());
  EXPECT_GE(lo, 20u);
}

}  // namespace
}  // namespace vigil::sim
