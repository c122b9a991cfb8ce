#include "frontend/frontend_evaluation.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace vigil::frontend {
namespace {

CameraFrame Frame(int64_t t_ns, std::vector<std::pair<int, Eigen::Vector2d>> obs) {
  CameraFrame frame;
  frame.t_ns = t_ns;
  for (const auto& [id, uv] : obs) frame.features.push_back({id, uv});
  return frame;
}

TEST(FrontendEvaluation, BinOfIsTheLastBinStartingAtOrBelowTheValue) {
  const std::vector<int> bins = {1, 2, 5};
  EXPECT_EQ(BinOf(bins, 0), std::nullopt);
  EXPECT_EQ(BinOf(bins, 1), 0u);
  EXPECT_EQ(BinOf(bins, 4), 1u);
  EXPECT_EQ(BinOf(bins, 5), 2u);
  EXPECT_EQ(BinOf(bins, 1000), 2u);  // the last bin is open
}

TEST(FrontendEvaluation, TrackLengthsAndTheirSummary) {
  const Eigen::Vector2d p(1, 1);
  // id 4: 3 frames, id 7: 1, id 2: 2, id 9: 1 (appears once, late)
  const std::vector<CameraFrame> frames = {Frame(0, {{4, p}, {7, p}}), Frame(1, {{2, p}, {4, p}}),
                                           Frame(2, {{2, p}, {4, p}, {9, p}})};
  EXPECT_EQ(TrackLengths(frames), (std::vector<int>{3, 1, 2, 1}));
  const TrackLengthSummary s = SummarizeTrackLengths({3, 1, 2, 1, 12}, {1, 2, 3, 10});
  EXPECT_EQ(s.tracks, 5);
  EXPECT_EQ(s.min, 1);
  EXPECT_EQ(s.max, 12);
  EXPECT_DOUBLE_EQ(s.median, 2.0);
  EXPECT_DOUBLE_EQ(s.mean, 19.0 / 5.0);
  ASSERT_EQ(s.histogram.size(), 4u);
  EXPECT_EQ(s.histogram[0].from, 1);
  EXPECT_EQ(s.histogram[0].to, 1);
  EXPECT_EQ(s.histogram[0].count, 2);
  EXPECT_EQ(s.histogram[1].count, 1);
  EXPECT_EQ(s.histogram[2].from, 3);
  EXPECT_EQ(s.histogram[2].to, 9);
  EXPECT_EQ(s.histogram[2].count, 1);
  EXPECT_EQ(s.histogram[3].to, -1);
  EXPECT_EQ(s.histogram[3].count, 1);
  // An even count takes the mean of the middle two; an empty list gives zeros and empty bins.
  EXPECT_DOUBLE_EQ(SummarizeTrackLengths({1, 2, 4, 8}, {1}).median, 3.0);
  const TrackLengthSummary empty = SummarizeTrackLengths({}, {1, 5});
  EXPECT_EQ(empty.tracks, 0);
  EXPECT_EQ(empty.histogram[1].count, 0);
}

TEST(FrontendEvaluation, ReprojectionErrorsSkipFirstObservationsAndUnknownTruth) {
  const std::vector<CameraFrame> frames = {
      Frame(0, {{1, {10, 10}}, {2, {20, 20}}}),
      Frame(1, {{1, {11, 10}}, {2, {20, 25}}, {3, {5, 5}}}),
      Frame(2, {{1, {12, 10.5}}, {3, {6, 5}}}),
  };
  const TruePixels truth = {
      {Eigen::Vector2d(10, 10), Eigen::Vector2d(20, 20)},
      {Eigen::Vector2d(11, 10), Eigen::Vector2d(20, 20), Eigen::Vector2d(5, 5)},
      {Eigen::Vector2d(12, 10), std::nullopt},
  };
  const ReprojectionEvaluation e = EvaluateReprojection(frames, truth, 2.0);
  EXPECT_EQ(e.observations, 7);
  EXPECT_EQ(e.first_observations, 3);
  EXPECT_EQ(e.without_truth, 1);
  ASSERT_EQ(e.errors_px.size(), 3u);
  EXPECT_DOUBLE_EQ(e.errors_px[0], 0.0);
  EXPECT_DOUBLE_EQ(e.errors_px[1], 5.0);
  EXPECT_DOUBLE_EQ(e.errors_px[2], 0.5);
  // Ages count frames since the track's first observation, including those without truth.
  EXPECT_EQ(e.ages_frames, (std::vector<int>{1, 1, 2}));
  // A track missing from a frame still ages with it: the age counts frames, not observations.
  const std::vector<CameraFrame> gap = {Frame(0, {{1, {10, 10}}}), Frame(1, {}), Frame(2, {{1, {10, 10}}})};
  const TruePixels gap_truth = {{Eigen::Vector2d(10, 10)}, {}, {Eigen::Vector2d(10, 10)}};
  EXPECT_EQ(EvaluateReprojection(gap, gap_truth, 2.0).ages_frames, (std::vector<int>{2}));
  EXPECT_EQ(e.outliers, 1);
  EXPECT_DOUBLE_EQ(e.outlier_ratio, 1.0 / 3.0);
  EXPECT_EQ(EvaluateReprojection(frames, truth, 5.0).outliers, 0);  // strictly above the threshold

  TruePixels wrong = truth;
  wrong.pop_back();
  EXPECT_THROW(EvaluateReprojection(frames, wrong, 2.0), std::invalid_argument);
}

TEST(FrontendEvaluation, OptionsValidation) {
  FrontendEvaluationOptions options;
  EXPECT_EQ(ValidateEvaluationOptions(options), "");
  options.track_length_bins = {1, 5, 5};
  EXPECT_NE(ValidateEvaluationOptions(options), "");
  options.track_length_bins = {};
  EXPECT_NE(ValidateEvaluationOptions(options), "");
}

}  // namespace
}  // namespace vigil::frontend
