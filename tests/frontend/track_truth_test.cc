#include "frontend/track_truth.h"

#include <cmath>

#include <gtest/gtest.h>

namespace vigil::frontend {
namespace {

// The ground plane z = 0 as the scene; nothing on a ray that does not go down.
std::optional<double> GroundPlane(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W) {
  if (dir_W.z() >= -1e-12) return std::nullopt;
  return -origin_W.z() / dir_W.z();
}

// A camera 3 m above the ground looking down (C z = -W z), moving along x and yawing.
Eigen::Isometry3d CameraPose(int64_t t_ns) {
  const double t = static_cast<double>(t_ns) * 1e-9;
  Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();
  T_WC.linear() = (Eigen::AngleAxisd(0.2 * t, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  T_WC.translation() = Eigen::Vector3d(0.5 * t, 0.1 * t, 3.0);
  return T_WC;
}

Eigen::Vector2d Project(const PinholeIntrinsics& k, const Eigen::Isometry3d& T_WC,
                        const Eigen::Vector3d& p_W) {
  const Eigen::Vector3d p_C = T_WC.inverse() * p_W;
  return {k.fx * p_C.x() / p_C.z() + k.cx, k.fy * p_C.y() / p_C.z() + k.cy};
}

TEST(TrackTruth, FirstObservationRayCastThenProjected) {
  const PinholeIntrinsics k{400.0, 410.0, 320.0, 240.0};
  const Eigen::Vector3d a_W(0.3, -0.4, 0.0), b_W(1.0, 0.6, 0.0);
  std::vector<CameraFrame> frames;
  for (int f = 0; f < 4; ++f) {
    const int64_t t_ns = f * 100'000'000LL;
    CameraFrame frame;
    frame.t_ns = t_ns;
    frame.features.push_back({5, Project(k, CameraPose(t_ns), a_W)});
    Eigen::Vector2d b = Project(k, CameraPose(t_ns), b_W);
    if (f == 2) b += Eigen::Vector2d(3.0, -4.0);  // a tracking error of 5 px
    frame.features.push_back({8, b});
    frames.push_back(frame);
  }
  // A pose unknown at the last frame; a track that begins there has no truth.
  frames.back().features.push_back({9, Eigen::Vector2d(100, 100)});
  const auto pose = [](int64_t t_ns) -> std::optional<Eigen::Isometry3d> {
    if (t_ns > 250'000'000) return std::nullopt;
    return CameraPose(t_ns);
  };
  const TruePixels truth = ComputeTruePixels(frames, k, pose, GroundPlane);
  ASSERT_EQ(truth.size(), 4u);
  for (int f = 0; f < 3; ++f) {
    const int64_t t_ns = frames[f].t_ns;
    ASSERT_TRUE(truth[f][0] && truth[f][1]);
    EXPECT_LT((*truth[f][0] - Project(k, CameraPose(t_ns), a_W)).norm(), 1e-9);
    EXPECT_LT((*truth[f][1] - Project(k, CameraPose(t_ns), b_W)).norm(), 1e-9);
  }
  EXPECT_NEAR((frames[2].features[1].uv_px - *truth[2][1]).norm(), 5.0, 1e-9);
  EXPECT_FALSE(truth[3][0]);
  EXPECT_FALSE(truth[3][2]);
}

TEST(TrackTruth, RayMissingTheSceneLeavesTheTrackUnknown) {
  const PinholeIntrinsics k{400.0, 400.0, 320.0, 240.0};
  std::vector<CameraFrame> frames(2);
  frames[0].t_ns = 0;
  frames[1].t_ns = 1;
  frames[0].features.push_back({1, Eigen::Vector2d(320, 240)});
  frames[1].features.push_back({1, Eigen::Vector2d(320, 240)});
  const auto pose = [](int64_t) -> std::optional<Eigen::Isometry3d> { return Eigen::Isometry3d::Identity(); };
  const auto miss = [](const Eigen::Vector3d&, const Eigen::Vector3d&) -> std::optional<double> {
    return std::nullopt;
  };
  const TruePixels truth = ComputeTruePixels(frames, k, pose, miss);
  EXPECT_FALSE(truth[0][0]);
  EXPECT_FALSE(truth[1][0]);
}

}  // namespace
}  // namespace vigil::frontend
