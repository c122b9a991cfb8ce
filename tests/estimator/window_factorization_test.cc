// The window's factorization against a dense one: the same solution and the same newest pose covariance,
// by the speed-bias chain where the window's structure allows it, densely where it does not.
#include "estimator/window_factorization.h"

#include <random>
#include <string>

#include <gtest/gtest.h>

namespace vigil::estimator {
namespace {

class WindowFactorizationTest : public ::testing::Test {
 protected:
  Eigen::MatrixXd RandomInformation(int rows, int cols) {
    Eigen::MatrixXd J(rows, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) J(i, j) = n01_(rng_);
    return J.transpose() * J;
  }
  // A window's information: each frame's own states, the IMU factors between neighbours' poses and
  // speed-biases, every pose with every pose (shared features), and a marginalization prior over the poses
  // and the oldest speed-bias block.
  Eigen::MatrixXd Window(int frames) {
    const int n = 15 * frames;
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
    for (int k = 0; k < frames; ++k) H.block(15 * k, 15 * k, 15, 15) += RandomInformation(20, 15);
    for (int k = 1; k < frames; ++k) H.block(15 * (k - 1), 15 * (k - 1), 30, 30) += RandomInformation(15, 30);
    const Eigen::MatrixXd poses = RandomInformation(40, 6 * frames);
    for (int i = 0; i < frames; ++i)
      for (int j = 0; j < frames; ++j) H.block(15 * i, 15 * j, 6, 6) += poses.block(6 * i, 6 * j, 6, 6);
    std::vector<int> prior_columns;
    for (int k = 0; k < frames; ++k)
      for (int c = 0; c < 6; ++c) prior_columns.push_back(15 * k + c);
    for (int c = 6; c < 15; ++c) prior_columns.push_back(c);
    const Eigen::MatrixXd prior = RandomInformation(10, static_cast<int>(prior_columns.size()));
    H(prior_columns, prior_columns) += prior;
    return H;
  }
  // The window with `points` landmark points after the frames: each point observed by a few poses, and the
  // prior over the points, the poses and the oldest speed-bias block (it couples them all).
  Eigen::MatrixXd WindowWithPoints(int frames, int points) {
    const int n = 15 * frames + 3 * points;
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
    H.topLeftCorner(15 * frames, 15 * frames) = Window(frames);
    std::vector<int> prior_columns;
    for (int j = 0; j < points; ++j) {
      const int point = 15 * frames + 3 * j;
      for (int c = 0; c < 3; ++c) prior_columns.push_back(point + c);
      for (int k = j % 3; k < frames; k += 2) {
        std::vector<int> observation;
        for (int c = 0; c < 6; ++c) observation.push_back(15 * k + c);
        for (int c = 0; c < 3; ++c) observation.push_back(point + c);
        H(observation, observation) += RandomInformation(2, 9);
      }
    }
    for (int c = 0; c < 15; ++c) prior_columns.push_back(c);
    const int prior_size = static_cast<int>(prior_columns.size());
    H(prior_columns, prior_columns) += RandomInformation(prior_size + 5, prior_size);
    return H;
  }
  Eigen::VectorXd RandomVector(int n) {
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i) v[i] = n01_(rng_);
    return v;
  }
  // Solve and the newest pose's covariance agree with a dense inverse.
  // `points`: the landmark points after the frames.
  void ExpectTheDenseAnswer(const Eigen::MatrixXd& H, const WindowFactorization& factorization,
                            int points = 0) {
    const Eigen::MatrixXd Sigma = H.inverse();
    const int newest = static_cast<int>(H.rows()) - 3 * points - 15;
    const Eigen::MatrixXd expected = Sigma.block(newest, newest, 6, 6);
    EXPECT_LT((factorization.NewestPoseCovariance() - expected).norm(), 1e-9 * expected.norm());
    const Eigen::VectorXd b = RandomVector(static_cast<int>(H.rows()));
    const Eigen::VectorXd x = Sigma * b;
    EXPECT_LT((factorization.Solve(b) - x).norm(), 1e-9 * x.norm());
  }

  std::mt19937_64 rng_{11};
  std::normal_distribution<double> n01_;
};

TEST_F(WindowFactorizationTest, TheSpeedBiasChainGivesTheDenseAnswer) {
  for (const int frames : {1, 2, 5, 16}) {
    SCOPED_TRACE(frames);
    const Eigen::MatrixXd H = Window(frames);
    WindowFactorization factorization;
    ASSERT_TRUE(factorization.Compute(H));
    EXPECT_TRUE(factorization.chain());
    ExpectTheDenseAnswer(H, factorization);
  }
}

TEST_F(WindowFactorizationTest, LandmarkPointsJoinThePosesSchurComplement) {
  for (const int frames : {2, 5, 16})
    for (const int points : {1, 7, 40}) {
      SCOPED_TRACE(std::to_string(frames) + " frames, " + std::to_string(points) + " points");
      Eigen::MatrixXd H = WindowWithPoints(frames, points);
      const Eigen::MatrixXd symmetric = H;
      H.triangularView<Eigen::StrictlyUpper>().setConstant(std::nan(""));
      WindowFactorization factorization;
      ASSERT_TRUE(factorization.Compute(H, points));
      EXPECT_TRUE(factorization.chain());
      ExpectTheDenseAnswer(symmetric, factorization, points);
    }
}

TEST_F(WindowFactorizationTest, OnlyTheLowerTriangleIsRead) {
  Eigen::MatrixXd H = Window(6);
  const Eigen::MatrixXd symmetric = H;
  H.triangularView<Eigen::StrictlyUpper>().setConstant(std::nan(""));
  WindowFactorization factorization;
  ASSERT_TRUE(factorization.Compute(H));
  ExpectTheDenseAnswer(symmetric, factorization);
}

TEST_F(WindowFactorizationTest, SpeedBiasBlocksCoupledBeyondNeighboursAreFactorizedDensely) {
  Eigen::MatrixXd H = Window(6);
  std::vector<int> columns;
  for (int c = 6; c < 15; ++c) columns.push_back(c);               // frame 0's speed-bias
  for (int c = 15 * 3 + 6; c < 15 * 4; ++c) columns.push_back(c);  // frame 3's
  H(columns, columns) += RandomInformation(12, 18);
  WindowFactorization factorization;
  ASSERT_TRUE(factorization.Compute(H));
  EXPECT_FALSE(factorization.chain());
  ExpectTheDenseAnswer(H, factorization);
}

TEST_F(WindowFactorizationTest, AMatrixThatIsNotPositiveDefiniteIsRefused) {
  for (const int block : {6, 15 * 3, 15 * 3 + 6, 15 * 5}) {  // speed-bias or pose blocks, oldest to newest
    SCOPED_TRACE(block);
    Eigen::MatrixXd H = Window(6);
    const int size = block % 15 == 0 ? 6 : 9;
    H.middleRows(block, size).setZero();
    H.middleCols(block, size).setZero();
    WindowFactorization factorization;
    EXPECT_FALSE(factorization.Compute(H));
  }
}

}  // namespace
}  // namespace vigil::estimator
