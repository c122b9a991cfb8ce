// WindowInformation against the general marginalization (EliminateDropped) on the same factors: a window of
// three frames with an IMU-like factor per interval, tracks observed with noise under a Cauchy loss, and a
// prior away from its linearization point.
#include "estimator/window_information.h"

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <ceres/loss_function.h>
#include <gtest/gtest.h>

#include "core/so3.h"
#include "estimator/marginalization.h"
#include "estimator/pose_covariance.h"
#include "estimator/pose_manifold.h"
#include "estimator/reprojection_factor.h"

namespace vigil::estimator {
namespace {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::vector<double> Pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  return {p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()};
}

Eigen::Vector2d Observe(const std::vector<double>& pose, const Eigen::Vector3d& l_W) {
  const Eigen::Vector3d p_C = PoseQ(pose.data()).conjugate() * (l_W - PoseP(pose.data()));
  return p_C.head<2>() / p_C.z();
}

// A nonlinear residual over two frames (pose, speed-bias, pose, speed-bias), 15 rows, with the estimator's
// Jacobian convention (tangent Jacobian of a pose in its first 6 columns): r = A [dp_0, phi_0, x_0, dp_1,
// phi_1, x_1] + sin(that), with phi the rotation vector of each pose.
class TwoFrameCost : public ceres::CostFunction {
 public:
  explicit TwoFrameCost(Eigen::MatrixXd A) : A_(std::move(A)) {
    set_num_residuals(15);
    *mutable_parameter_block_sizes() = {kPoseSize, kSpeedBiasSize, kPoseSize, kSpeedBiasSize};
  }
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override {
    Eigen::Matrix<double, 30, 1> v;
    for (int f = 0; f < 2; ++f) {
      v.segment<3>(15 * f) = PoseP(x[2 * f]);
      v.segment<3>(15 * f + 3) = LogQ(PoseQ(x[2 * f]));
      v.segment<9>(15 * f + 6) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(x[2 * f + 1]);
    }
    const Eigen::VectorXd u = A_ * v;
    Eigen::Map<Eigen::VectorXd>(residuals, 15) = u + u.array().sin().matrix();
    if (jacobians == nullptr) return true;
    // d r / d v = (I + diag(cos u)) A; a pose's rotation enters through phi = Log(q): d phi / d theta =
    // Jr^-1(phi) for a right perturbation.
    const Eigen::MatrixXd D = (Eigen::VectorXd::Ones(15) + u.array().cos().matrix()).asDiagonal() * A_;
    for (int f = 0; f < 2; ++f) {
      Eigen::Map<RowMajorMatrix> J_pose(jacobians[2 * f], 15, kPoseSize);
      J_pose.setZero();
      J_pose.leftCols<3>() = D.middleCols<3>(15 * f);
      J_pose.middleCols<3>(3) = D.middleCols<3>(15 * f + 3) * RightJacobianInverse(v.segment<3>(15 * f + 3));
      Eigen::Map<RowMajorMatrix>(jacobians[2 * f + 1], 15, kSpeedBiasSize) = D.middleCols<9>(15 * f + 6);
    }
    return true;
  }

 private:
  Eigen::MatrixXd A_;
};

TEST(WindowInformation, EqualsTheGeneralSchurComplementOfTheDepths) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n01;
  const int frames = 3;
  std::vector<std::vector<double>> poses, speed_biases(frames, std::vector<double>(kSpeedBiasSize));
  for (int k = 0; k < frames; ++k) {
    poses.push_back(Pose(Eigen::Vector3d(0.3 * k, 0.1 * std::sin(k), 0.05 * k),
                         ExpQ(Eigen::Vector3d(0.02 * k, -0.03 * k, 0.1 + 0.2 * k))));
    for (double& x : speed_biases[k]) x = 0.1 * n01(rng);
  }
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  std::vector<MarginalizationTerm> terms;
  for (int k = 1; k < frames; ++k) {
    Eigen::MatrixXd A(15, 30);
    for (int i = 0; i < A.size(); ++i) A.data()[i] = 0.3 * n01(rng);
    costs.push_back(std::make_unique<TwoFrameCost>(A));
    terms.push_back(
        {costs.back().get(),
         nullptr,
         {poses[k - 1].data(), speed_biases[k - 1].data(), poses[k].data(), speed_biases[k].data()}});
  }
  // Tracks anchored in frames 0 and 1, observed with noise in the later frames; inverse depths 2 % off.
  const ceres::CauchyLoss loss(1.0);
  const Eigen::Isometry3d T_BC = Eigen::Isometry3d::Identity();
  const int tracks = 10;
  std::vector<double> inv_depths(tracks);
  std::vector<std::vector<WindowInformation::Reprojection>> track_terms(tracks);
  std::vector<std::unique_ptr<ReprojectionFactor>> factors;
  DroppedBlocks dropped;
  std::vector<MarginalizationTerm> reprojection_terms;
  for (int i = 0; i < tracks; ++i) {
    const Eigen::Vector3d l_W(-1.0 + 0.25 * i, 0.4 * std::cos(i), 3.0 + 0.3 * i);
    const int anchor = i % 2;
    const Eigen::Vector3d p_C = PoseQ(poses[anchor].data()).conjugate() * (l_W - PoseP(poses[anchor].data()));
    inv_depths[i] = 1.02 / p_C.z();
    dropped.push_back(&inv_depths[i]);
    for (int k = anchor + 1; k < frames; ++k) {
      const Eigen::Vector2d noise(0.01 * n01(rng), 0.01 * n01(rng));
      factors.push_back(std::make_unique<ReprojectionFactor>(Observe(poses[anchor], l_W),
                                                             Observe(poses[k], l_W) + noise, T_BC, 300.0));
      track_terms[i].push_back(
          {factors.back().get(), {poses[anchor].data(), poses[k].data(), &inv_depths[i]}});
      reprojection_terms.push_back(
          {factors.back().get(), &loss, {poses[anchor].data(), poses[k].data(), &inv_depths[i]}});
    }
  }
  // A prior on frame 1's pose and frame 2's states, linearized elsewhere.
  LinearPrior prior;
  for (double* block : {poses[1].data(), poses[2].data(), speed_biases[2].data()}) {
    const int size = block == speed_biases[2].data() ? kSpeedBiasSize : kPoseSize;
    LinearPrior::Block b{block, size, TangentSizeOf(size), std::vector<double>(block, block + size)};
    if (size == kPoseSize) {
      const Eigen::Vector3d dtheta(0.01, -0.02, 0.03);
      Eigen::Map<Eigen::Quaterniond>(b.x0.data() + 3) = PoseQ(block) * ExpQ(dtheta);
      b.x0[0] += 0.05;
    }
    prior.blocks.push_back(b);
  }
  const int prior_columns = 6 + 6 + 9;
  Eigen::MatrixXd R(prior_columns, prior_columns);
  for (int i = 0; i < R.size(); ++i) R.data()[i] = n01(rng);
  prior.J = R.triangularView<Eigen::Upper>();
  prior.r = Eigen::VectorXd::Random(prior_columns);
  prior.H = prior.J.transpose() * prior.J;
  prior.g = prior.J.transpose() * prior.r;

  std::vector<double*> pose_blocks, speed_bias_blocks;
  for (int k = 0; k < frames; ++k) {
    pose_blocks.push_back(poses[k].data());
    speed_bias_blocks.push_back(speed_biases[k].data());
  }
  WindowInformation information(pose_blocks, speed_bias_blocks);
  for (const MarginalizationTerm& t : terms)
    ASSERT_TRUE(information.AddFactor(*t.cost, nullptr, {t.blocks.begin(), t.blocks.end()}));
  for (const auto& track : track_terms)
    ASSERT_TRUE(information.AddTrack(track.data(), track.data() + track.size(), &loss, 1e-8));
  ASSERT_TRUE(information.AddPrior(prior));

  terms.insert(terms.end(), reprojection_terms.begin(), reprojection_terms.end());
  SchurComplement expected;
  ASSERT_TRUE(EliminateDropped(&prior, terms, dropped, 1e-8, &expected));
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
  EXPECT_EQ(information.BlockSizes(), (std::vector<int>{6, 9, 6, 9, 6, 9}));
}

TEST(WindowInformation, RefusesABlockOutsideTheWindow) {
  std::vector<double> pose = Pose(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
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
