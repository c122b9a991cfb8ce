// ReprojectionFactorCache: one factor per (track, anchor, observation), reused while the pair lives, rebuilt
// when the anchor changes, released with the track; the terms name the right parameter blocks.
#include "estimator/reprojection_factor_cache.h"

#include <map>
#include <vector>

#include <gtest/gtest.h>

namespace vigil::estimator {
namespace {

FeatureTrack Track(const std::vector<uint64_t>& frames) {
  FeatureTrack track;
  for (const uint64_t f : frames) track.observations.push_back({f, Eigen::Vector2d(0.01 * f, -0.02 * f)});
  track.inv_depth = 0.2;
  track.has_depth = true;
  return track;
}

class ReprojectionFactorCacheTest : public ::testing::Test {
 protected:
  std::vector<ReprojectionFactorCache::Term> Terms(int id, const FeatureTrack& track) {
    std::vector<ReprojectionFactorCache::Term> terms;
    cache_.AppendTerms(
        id, track, [&](uint64_t frame) { return poses_[frame].data(); }, &inv_depth_, &terms);
    return terms;
  }

  ReprojectionFactorCache cache_{Eigen::Isometry3d::Identity(), 460.0};
  std::map<uint64_t, std::vector<double>> poses_;
  double inv_depth_ = 0.5;
};

TEST_F(ReprojectionFactorCacheTest, ReusesFactorsWhileTheirObservationsLive) {
  const auto first = Terms(7, Track({1, 2, 3}));
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(cache_.size(), 2u);
  for (std::size_t k = 0; k < first.size(); ++k) {
    EXPECT_EQ(first[k].blocks[0], poses_[1].data());  // the anchor's pose
    EXPECT_EQ(first[k].blocks[1], poses_[k + 2].data());
    EXPECT_EQ(first[k].blocks[2], &inv_depth_);
  }
  // Asked again with the track unchanged: the same factors on the same blocks.
  const auto again = Terms(7, Track({1, 2, 3}));
  ASSERT_EQ(again.size(), 2u);
  for (std::size_t k = 0; k < first.size(); ++k) {
    EXPECT_EQ(again[k].factor, first[k].factor);
    EXPECT_EQ(again[k].blocks, first[k].blocks);
  }
  EXPECT_EQ(cache_.size(), 2u);
  // Frame 2 left the window and frame 4 observed the track: (1, 3) is reused, (1, 4) is new.
  const auto second = Terms(7, Track({1, 3, 4}));
  ASSERT_EQ(second.size(), 2u);
  EXPECT_EQ(second[0].factor, first[1].factor);
  EXPECT_NE(second[1].factor, first[0].factor);
  EXPECT_EQ(cache_.size(), 2u);
  // The anchor changed (frame 1 marginalized): every factor is rebuilt.
  const auto third = Terms(7, Track({3, 4}));
  ASSERT_EQ(third.size(), 1u);
  EXPECT_NE(third[0].factor, second[1].factor);
  EXPECT_EQ(third[0].blocks[0], poses_[3].data());
  EXPECT_EQ(cache_.size(), 1u);
}

TEST_F(ReprojectionFactorCacheTest, CachedFactorEvaluatesAsAFreshOne) {
  poses_[1] = {0, 0, 0, 0, 0, 0, 1};
  poses_[2] = {0.3, -0.1, 0.05, 0, 0, 0.0998334, 0.9950042};
  Terms(3, Track({1, 2}));
  const auto terms = Terms(3, Track({1, 2}));
  const FeatureTrack track = Track({1, 2});
  const ReprojectionFactor fresh(track.observations[0].second, track.observations[1].second,
                                 Eigen::Isometry3d::Identity(), 460.0);
  const double* blocks[3] = {poses_[1].data(), poses_[2].data(), &inv_depth_};
  double cached_r[2], fresh_r[2];
  ASSERT_TRUE(terms[0].factor->Evaluate(blocks, cached_r, nullptr));
  ASSERT_TRUE(fresh.Evaluate(blocks, fresh_r, nullptr));
  EXPECT_EQ(cached_r[0], fresh_r[0]);
  EXPECT_EQ(cached_r[1], fresh_r[1]);
}

TEST_F(ReprojectionFactorCacheTest, KeepTracksReleasesTheOthers) {
  Terms(1, Track({1, 2, 3}));
  Terms(2, Track({2, 3}));
  EXPECT_EQ(cache_.size(), 3u);
  std::map<int, FeatureTrack> live;
  live[2] = Track({2, 3});
  cache_.KeepTracks(live);
  EXPECT_EQ(cache_.size(), 1u);
  cache_.Clear();
  EXPECT_EQ(cache_.size(), 0u);
}

}  // namespace
}  // namespace vigil::estimator
