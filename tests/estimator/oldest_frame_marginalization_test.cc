// OldestFrameMarginalization against the general marginalization (Marginalize, MarginalizeInformation) of the
// same terms: the synthetic window's frame 0 with its factor to frame 1 and the tracks anchored in it, with
// and without a previous prior away from its linearization point.
#include "estimator/oldest_frame_marginalization.h"

#include <vector>

#include <gtest/gtest.h>

#include "estimator/marginalization.h"
#include "tests/estimator/synthetic_window.h"

namespace vigil::estimator {
namespace {

OldestFrame OldestOf(testing::SyntheticWindow& w) {
  OldestFrame oldest;
  oldest.poses = w.pose_blocks;
  oldest.speed_biases = w.speed_bias_blocks;
  oldest.factors = {w.terms.front()};  // the factor from frame 0 to frame 1
  for (const auto& track : w.track_terms)
    if (track.front().blocks[0] == w.pose_blocks.front()) oldest.tracks.push_back(track);
  oldest.reprojection_loss = &w.loss;
  return oldest;
}

void ExpectSameBlocks(const LinearPrior& actual, const LinearPrior& expected) {
  ASSERT_EQ(actual.blocks.size(), expected.blocks.size());
  for (std::size_t k = 0; k < expected.blocks.size(); ++k) {
    EXPECT_EQ(actual.blocks[k].address, expected.blocks[k].address) << "block " << k;
    EXPECT_EQ(actual.blocks[k].size, expected.blocks[k].size) << "block " << k;
    EXPECT_EQ(actual.blocks[k].x0, expected.blocks[k].x0) << "block " << k;
  }
}

// The tolerances are relative to the information's scale: the oldest frame's factor leaves frame 1's
// speed-bias without information once frame 0 is eliminated, so the complement is singular there and its
// gradient near zero.
void ExpectSameInformation(const LinearPrior& actual, const LinearPrior& expected) {
  ExpectSameBlocks(actual, expected);
  ASSERT_EQ(actual.H.rows(), expected.H.rows());
  const double scale = expected.H.norm();
  EXPECT_GT(scale, 1.0);
  EXPECT_LT((actual.H - expected.H).norm(), 1e-10 * scale);
  EXPECT_LT((actual.g - expected.g).norm(), 1e-10 * scale);
}

// A square-root prior reproduces its information form: J^T J and J^T r, up to the ridge (Cholesky) or the
// eigenvalues at the threshold it drops (the eigen-decomposition, which rounding can choose on a singular
// complement).
void ExpectSquareRootOf(const LinearPrior& square_root, const LinearPrior& information) {
  ExpectSameBlocks(square_root, information);
  ASSERT_GT(square_root.J.rows(), 0);
  ASSERT_EQ(square_root.J.cols(), information.H.cols());
  const double scale = information.H.norm();
  const Eigen::MatrixXd JtJ = square_root.J.transpose() * square_root.J;
  const Eigen::VectorXd Jtr = square_root.J.transpose() * square_root.r;
  EXPECT_LT((JtJ - information.H).norm(), 1e-6 * scale);
  EXPECT_LT((Jtr - information.g).norm(), 1e-6 * scale);
}

TEST(OldestFrameMarginalization, EqualsTheGeneralMarginalizationOfTheSameTerms) {
  testing::SyntheticWindow w(5);
  const OldestFrame oldest = OldestOf(w);
  ASSERT_EQ(oldest.tracks.size(), 5u);
  const std::vector<MarginalizationTerm> terms = GeneralTerms(oldest);
  const DroppedBlocks dropped = GeneralDroppedBlocks(oldest);
  EXPECT_EQ(terms.size(), 1u + 5u * 2u);  // the factor, then two reprojections per track
  EXPECT_EQ(dropped.size(), 2u + 5u);     // frame 0's blocks, then the depths
  // The terms linearized once give every prior, as the estimator uses them.
  const OldestFrameMarginalization shared(oldest, 1e-8);
  for (const LinearPrior* previous : std::vector<const LinearPrior*>{nullptr, &w.prior}) {
    SCOPED_TRACE(previous ? "with a previous prior" : "without a previous prior");
    LinearPrior information, expected_information;
    ASSERT_TRUE(shared.Prior(previous, PriorForm::kInformation, &information));
    ASSERT_TRUE(MarginalizeInformation(previous, terms, dropped, 1e-8, &expected_information));
    ExpectSameInformation(information, expected_information);
    EXPECT_EQ(information.J.size(), 0);

    LinearPrior square_root, expected_square_root;
    ASSERT_TRUE(shared.Prior(previous, PriorForm::kSquareRoot, &square_root));
    ASSERT_TRUE(Marginalize(previous, terms, dropped, 1e-8, &expected_square_root));
    ExpectSquareRootOf(square_root, information);
    ExpectSquareRootOf(expected_square_root, information);
  }
  // Away from its linearization point the previous prior makes a gradient to compare.
  LinearPrior with_prior;
  ASSERT_TRUE(shared.Prior(&w.prior, PriorForm::kInformation, &with_prior));
  EXPECT_GT(with_prior.g.norm(), 1e-3);
}

// Kept: frame 1's blocks and frame 2's pose (the tracks' observations); with the prior, its blocks first.
TEST(OldestFrameMarginalization, KeepsTheBlocksInTheGeneralOrder) {
  testing::SyntheticWindow w(7);
  const OldestFrame oldest = OldestOf(w);
  LinearPrior prior;
  ASSERT_TRUE(MarginalizeOldestFrame(nullptr, oldest, 1e-8, PriorForm::kSquareRoot, &prior));
  std::vector<const double*> blocks;
  for (const LinearPrior::Block& b : prior.blocks) blocks.push_back(b.address);
  EXPECT_EQ(blocks, (std::vector<const double*>{w.pose_blocks[1], w.speed_bias_blocks[1], w.pose_blocks[2]}));
  ASSERT_TRUE(MarginalizeOldestFrame(&w.prior, oldest, 1e-8, PriorForm::kSquareRoot, &prior));
  blocks.clear();
  for (const LinearPrior::Block& b : prior.blocks) blocks.push_back(b.address);
  EXPECT_EQ(blocks, (std::vector<const double*>{w.pose_blocks[1], w.pose_blocks[2], w.speed_bias_blocks[2],
                                                w.speed_bias_blocks[1]}));
}

TEST(OldestFrameMarginalization, FailsOnABlockOutsideTheWindow) {
  testing::SyntheticWindow w(9);
  OldestFrame oldest = OldestOf(w);
  std::vector<double> foreign(kSpeedBiasSize, 0.0);
  MarginalizationTerm term = oldest.factors.front();
  term.blocks = {w.pose_blocks[0], w.speed_bias_blocks[0], w.pose_blocks[1], foreign.data()};
  oldest.factors.push_back(term);
  LinearPrior prior;
  EXPECT_FALSE(MarginalizeOldestFrame(nullptr, oldest, 1e-8, PriorForm::kSquareRoot, &prior));
}

}  // namespace
}  // namespace vigil::estimator
