// The keyframe parallax of FeatureManager: raw image displacement, or with the frames' rotation removed.
#include "estimator/feature_manager.h"

#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "core/so3.h"

namespace vigil::estimator {
namespace {

// Normalized observation of the point p_A (in camera a) from camera b, with b = R_AB, t_AB in a.
Eigen::Vector2d Observe(const Eigen::Vector3d& p_A, const Eigen::Matrix3d& R_AB,
                        const Eigen::Vector3d& t_AB) {
  const Eigen::Vector3d p_B = R_AB.transpose() * (p_A - t_AB);
  return p_B.head<2>() / p_B.z();
}

// Two frames of a few points 4 to 12 m away, the second turned by R_AB and moved by t_AB.
FeatureManager TwoFrames(const Eigen::Matrix3d& R_AB, const Eigen::Vector3d& t_AB) {
  FeatureManager features{FeatureOptions{}};
  const Eigen::Vector3d points[] = {{-1.0, 0.5, 4.0}, {0.8, -0.6, 6.0}, {2.0, 1.0, 12.0}, {-0.5, -1.5, 8.0}};
  std::map<int, Eigen::Vector2d> a, b;
  for (int i = 0; i < 4; ++i) {
    a[i] = Observe(points[i], Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    b[i] = Observe(points[i], R_AB, t_AB);
  }
  features.AddFrame(0, a);
  features.AddFrame(1, b);
  return features;
}

TEST(FeatureManagerTest, RotationCompensatedParallaxIgnoresTurningOnTheSpot) {
  const Eigen::Matrix3d R_AB = ExpQ(Eigen::Vector3d(0.01, 0.05, -0.02)).toRotationMatrix();  // about 3 deg
  const FeatureManager turn = TwoFrames(R_AB, Eigen::Vector3d::Zero());
  // Raw: the turn moves every point by about 0.05 on the normalized plane (23 px at fx 460).
  EXPECT_GT(turn.MeanParallax(0, 1), 0.04);
  // Compensated with the relative rotation R_CbCa = R_AB^T: nothing is left.
  EXPECT_LT(turn.MeanParallax(0, 1, R_AB.transpose()), 1e-12);
}

TEST(FeatureManagerTest, RotationCompensatedParallaxKeepsTheTranslation) {
  const Eigen::Vector3d t_AB(0.3, 0.0, 0.0);  // sideways
  const FeatureManager slide = TwoFrames(Eigen::Matrix3d::Identity(), t_AB);
  const double translation_only = slide.MeanParallax(0, 1);
  EXPECT_GT(translation_only, 0.02);
  // The same translation with a turn: compensation gives back the parallax of the translation alone.
  const Eigen::Matrix3d R_AB = ExpQ(Eigen::Vector3d(0.0, 0.08, 0.0)).toRotationMatrix();
  const FeatureManager slide_and_turn = TwoFrames(R_AB, t_AB);
  EXPECT_GT(std::abs(slide_and_turn.MeanParallax(0, 1) - translation_only), 0.02);
  // Rotating a's rays into b removes the turn; the translation's parallax is then measured in b's image
  // instead of a's (equal to first order).
  EXPECT_NEAR(slide_and_turn.MeanParallax(0, 1, R_AB.transpose()), translation_only, 0.1 * translation_only);
  // Identity compensation is the raw displacement, bit for bit.
  EXPECT_EQ(slide_and_turn.MeanParallax(0, 1, Eigen::Matrix3d::Identity()),
            slide_and_turn.MeanParallax(0, 1));
}

TEST(FeatureManagerTest, AnErasedTrackStartsOverAtItsNextObservation) {
  FeatureManager features = TwoFrames(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.3, 0.0, 0.0));
  features.EraseTrack(2);
  ASSERT_EQ(features.tracks().count(2), 0u);
  ASSERT_EQ(features.tracks().size(), 3u);
  const std::map<int, Eigen::Vector2d> c = {{1, {0.1, 0.2}}, {2, {0.3, 0.4}}};
  EXPECT_EQ(features.AddFrame(7, c), 1);  // track 1 continues, track 2 starts over
  EXPECT_EQ(features.tracks().at(2).anchor_frame(), 7u);
  EXPECT_EQ(features.tracks().at(2).observations.size(), 1u);
  EXPECT_EQ(features.tracks().at(1).observations.size(), 3u);
}

}  // namespace
}  // namespace vigil::estimator
