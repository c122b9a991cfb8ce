#include "estimator/init/window_sfm.h"

#include <gtest/gtest.h>

#include "synthetic_scene.h"

namespace vigil::estimator {
namespace {

struct Window {
  std::vector<Eigen::Matrix3d> R_WC;
  std::vector<Eigen::Vector3d> p_WC;
  std::vector<Eigen::Vector3d> points_W;
  std::vector<FeatureMap> frames;
};

// 11 frames of a camera sliding sideways (step_m per frame) and turning slightly, looking at points 4-10 m
// ahead.
Window MakeWindow(uint64_t seed, double step_m, double noise, double turn = 1.0) {
  Rng rng(seed, "test_window_sfm");
  Window w;
  w.points_W = testing::RandomPoints(rng, 60, 4.0, 4.0, 10.0);
  for (int k = 0; k < 11; ++k) {
    w.R_WC.push_back(ExpQ(turn * Eigen::Vector3d(0.01 * k, -0.02 * k, 0.005 * k)).toRotationMatrix());
    w.p_WC.emplace_back(step_m * k, 0.02 * k * step_m / 0.15, 0.01 * k);
    FeatureMap f;
    const Eigen::Matrix3d R_CW = w.R_WC.back().transpose();
    const Eigen::Vector3d p_CW = -R_CW * w.p_WC.back();
    for (std::size_t i = 0; i < w.points_W.size(); ++i) {
      if (k > 5 && i % 7 == 0) continue;   // some tracks end, so frames see different subsets
      if (k < 3 && i % 11 == 0) continue;  // and some start late
      f[static_cast<int>(i)] = testing::Observe(R_CW, p_CW, w.points_W[i], rng, noise);
    }
    w.frames.push_back(f);
  }
  return w;
}

void ExpectMatchesTruth(const Window& w, const WindowSfmResult& r, double rot_tol_rad, double pos_tol) {
  const std::size_t l = static_cast<std::size_t>(r.reference_frame);
  const Eigen::Matrix3d R_LW = w.R_WC[l].transpose();
  const double scale = (R_LW * (w.p_WC.back() - w.p_WC[l])).norm();
  for (std::size_t i = 0; i < w.frames.size(); ++i) {
    const Eigen::Matrix3d R_LC = R_LW * w.R_WC[i];
    const Eigen::Vector3d p_LC = R_LW * (w.p_WC[i] - w.p_WC[l]) / scale;
    EXPECT_LT(testing::RotationErrorRad(r.q_LC[i].toRotationMatrix(), R_LC), rot_tol_rad) << "frame " << i;
    EXPECT_LT((r.p_LC[i] - p_LC).norm(), pos_tol) << "frame " << i;
  }
  for (const auto& [id, p_L] : r.points_L) {
    const Eigen::Vector3d truth = R_LW * (w.points_W[static_cast<std::size_t>(id)] - w.p_WC[l]) / scale;
    EXPECT_LT((p_L - truth).norm(), 20 * pos_tol) << "point " << id;
  }
}

TEST(WindowSfm, ReconstructsPosesAndPointsUpToScale) {
  const Window w = MakeWindow(1, 0.15, 0.0);
  WindowSfmResult r;
  ASSERT_TRUE(WindowSfm(w.frames, WindowSfmOptions{}, &r)) << r.failure_reason;
  EXPECT_GE(r.reference_frame, 0);
  EXPECT_LT(r.rms_reprojection, 1e-8);
  EXPECT_GE(r.points_L.size(), 55u);
  ExpectMatchesTruth(w, r, 1e-6, 1e-6);
}

TEST(WindowSfm, NoisyTracksStayClose) {
  const Window w = MakeWindow(2, 0.15, 0.5 / 460);
  WindowSfmResult r;
  ASSERT_TRUE(WindowSfm(w.frames, WindowSfmOptions{}, &r)) << r.failure_reason;
  EXPECT_LT(r.rms_reprojection, 1.0 / 460);
  ExpectMatchesTruth(w, r, 0.5 * M_PI / 180, 0.03);
}

TEST(WindowSfm, ReferenceFrameNeedsParallax) {
  // Steps of 1 cm without turning: about 8 px of parallax over the whole window, below the 30 px required.
  const Window w = MakeWindow(3, 0.01, 0.0, 0.0);
  WindowSfmResult r;
  EXPECT_FALSE(WindowSfm(w.frames, WindowSfmOptions{}, &r));
  EXPECT_NE(r.failure_reason.find("no reference frame"), std::string::npos) << r.failure_reason;
}

TEST(MeanParallax, AveragesOverSharedFeaturesOnly) {
  const FeatureMap a = {{1, {0, 0}}, {2, {0.1, 0}}, {3, {0, 0}}};
  const FeatureMap b = {{1, {0.3, 0.4}}, {2, {0.1, 0.1}}, {4, {5, 5}}};
  int shared = 0;
  EXPECT_DOUBLE_EQ(MeanParallax(a, b, &shared), 0.3);
  EXPECT_EQ(shared, 2);
}

}  // namespace
}  // namespace vigil::estimator
