// WindowInformation against the general marginalization (EliminateDropped) on the same factors: a window of
// three frames with an IMU-like factor per interval, tracks observed with noise under a Cauchy loss, and a
// prior away from its linearization point.
#include "estimator/window_information.h"

#include <vector>

#include <gtest/gtest.h>

#include "estimator/marginalization.h"
#include "estimator/pose_covariance.h"
#include "estimator/pose_manifold.h"
#include "tests/estimator/synthetic_window.h"

namespace vigil::estimator {
namespace {

TEST(WindowInformation, EqualsTheGeneralSchurComplementOfTheDepths) {
  testing::SyntheticWindow w(3);
  const int frames = testing::SyntheticWindow::frames;
  const auto& poses = w.poses;
  const auto& speed_biases = w.speed_biases;
  WindowInformation information(w.pose_blocks, w.speed_bias_blocks);
  for (const MarginalizationTerm& t : w.terms) ASSERT_TRUE(information.AddFactor(*t.cost, nullptr, t.blocks));
  for (const auto& track : w.track_terms)
    ASSERT_TRUE(information.AddTrack(track.data(), track.data() + track.size(), &w.loss, 1e-8));
  ASSERT_TRUE(information.AddPrior(w.prior));

  std::vector<MarginalizationTerm> terms = w.terms;
  terms.insert(terms.end(), w.reprojection_terms.begin(), w.reprojection_terms.end());
  SchurComplement expected;
  ASSERT_TRUE(EliminateDropped(&w.prior, terms, w.dropped, 1e-8, &expected));
  // Reorder the expected blocks into the window's layout.
  const int n = WindowInformation::kFrameSize * frames;
  ASSERT_EQ(expected.H.rows(), n);
  std::vector<int> column_of_expected;
  for (const LinearPrior::Block& b : expected.blocks)
    for (int k = 0; k < frames; ++k) {
      if (b.address == poses[k].data())
        for (int i = 0; i < 6; ++i) column_of_expected.push_back(WindowInformation::PoseColumn(k) + i);
      if (b.address == speed_biases[k].data())
        for (int i = 0; i < 9; ++i) column_of_expected.push_back(WindowInformation::SpeedBiasColumn(k) + i);
    }
  ASSERT_EQ(static_cast<int>(column_of_expected.size()), n);
  Eigen::MatrixXd H(n, n);
  Eigen::VectorXd g(n);
  for (int i = 0; i < n; ++i) {
    g[column_of_expected[i]] = expected.g[i];
    for (int j = 0; j < n; ++j) H(column_of_expected[i], column_of_expected[j]) = expected.H(i, j);
  }
  EXPECT_GT(g.norm(), 1.0);  // the noise, the prior's offset and the depth errors make a gradient
  EXPECT_LT((information.H() - H).norm(), 1e-10 * H.norm());
  EXPECT_LT((information.g() - g).norm(), 1e-10 * g.norm());
}

// With the fill kept apart, H() and g() hold the information before the depths' elimination, and
// subtracting the fill gives the eliminated one.
TEST(WindowInformation, TheSeparateDepthFillIsWhatTheEliminationSubtracts) {
  testing::SyntheticWindow w(3);
  auto build = [&](bool separate) {
    WindowInformation information(w.pose_blocks, w.speed_bias_blocks);
    for (const MarginalizationTerm& t : w.terms)
      EXPECT_TRUE(information.AddFactor(*t.cost, nullptr, t.blocks));
    if (separate) information.SeparateDepthFill();
    for (const auto& track : w.track_terms)
      EXPECT_TRUE(information.AddTrack(track.data(), track.data() + track.size(), &w.loss, 1e-8));
    return information;
  };
  const WindowInformation eliminated = build(false), separate = build(true);
  // The fill is over the poses alone.
  ASSERT_EQ(separate.depth_fill_H().rows(), WindowInformation::FillColumn(separate.frames()));
  EXPECT_GT(separate.depth_fill_H().norm(), 1e-3 * eliminated.H().norm());
  Eigen::MatrixXd eliminated_again = separate.H();
  WindowInformation::AddPoseBlocks(separate.depth_fill_H(), -1.0, &eliminated_again);
  EXPECT_LT((eliminated_again - eliminated.H()).norm(), 1e-12 * eliminated.H().norm());
  EXPECT_LT((separate.g() - separate.depth_fill_g() - eliminated.g()).norm(), 1e-12 * eliminated.g().norm());
}

// The information of some terms plus that of the others is the information of all of them: the covariance
// adds the oldest frame's share, linearized for its marginalization, to the rest's.
TEST(WindowInformation, ThePartsAddUpToTheWhole) {
  testing::SyntheticWindow w(3);
  WindowInformation whole(w.pose_blocks, w.speed_bias_blocks), first(w.pose_blocks, w.speed_bias_blocks),
      second(w.pose_blocks, w.speed_bias_blocks);
  for (std::size_t i = 0; i < w.terms.size(); ++i) {
    ASSERT_TRUE(whole.AddFactor(*w.terms[i].cost, nullptr, w.terms[i].blocks));
    ASSERT_TRUE((i % 2 == 0 ? first : second).AddFactor(*w.terms[i].cost, nullptr, w.terms[i].blocks));
  }
  for (std::size_t i = 0; i < w.track_terms.size(); ++i) {
    const auto& track = w.track_terms[i];
    ASSERT_TRUE(whole.AddTrack(track.data(), track.data() + track.size(), &w.loss, 1e-8));
    ASSERT_TRUE(
        (i % 2 == 0 ? second : first).AddTrack(track.data(), track.data() + track.size(), &w.loss, 1e-8));
  }
  ASSERT_TRUE(first.Add(second));
  EXPECT_GT((second.H() - whole.H()).norm(), 1e-3 * whole.H().norm());  // each part is only a part
  EXPECT_LT((first.H() - whole.H()).norm(), 1e-12 * whole.H().norm());
  EXPECT_LT((first.g() - whole.g()).norm(), 1e-12 * whole.g().norm());
  // Another window's, or one whose depth fill is kept apart, is refused.
  std::vector<double> pose = testing::Pose(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
  std::vector<double> speed_bias(kSpeedBiasSize, 0.0);
  EXPECT_FALSE(first.Add(WindowInformation({pose.data()}, {speed_bias.data()})));
  WindowInformation separate(w.pose_blocks, w.speed_bias_blocks);
  separate.SeparateDepthFill();
  EXPECT_FALSE(first.Add(separate));
}

TEST(WindowInformation, RefusesABlockOutsideTheWindow) {
  std::vector<double> pose = testing::Pose(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
  std::vector<double> speed_bias(kSpeedBiasSize, 0.0), other_pose = pose;
  WindowInformation information({pose.data()}, {speed_bias.data()});
  LinearPrior prior = GaugePrior(other_pose.data());
  EXPECT_FALSE(information.AddPrior(prior));
  prior = GaugePrior(pose.data());
  EXPECT_TRUE(information.AddPrior(prior));
  EXPECT_GT((information.H().block<3, 3>(0, 0).trace()), 0.0);
}

}  // namespace
}  // namespace vigil::estimator
