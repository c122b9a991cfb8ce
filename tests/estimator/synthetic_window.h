// A synthetic window for the estimator's linear algebra tests: three frames with a nonlinear IMU-like
// factor per interval, tracks anchored in frames 0 and 1 observed with noise in the later frames (inverse
// depths 2 % off, a Cauchy loss), and a prior on frame 1's pose and frame 2's states away from its
// linearization point. Built in place (it holds pointers into itself): neither copied nor moved.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/loss_function.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/so3.h"
#include "estimator/marginalization.h"
#include "estimator/pose_manifold.h"
#include "estimator/reprojection_factor.h"
#include "estimator/window_information.h"

namespace vigil::estimator::testing {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

inline std::vector<double> Pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  return {p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()};
}

inline Eigen::Vector2d Observe(const std::vector<double>& pose, const Eigen::Vector3d& l_W) {
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

struct SyntheticWindow {
  static constexpr int frames = 3;
  static constexpr int tracks = 10;

  explicit SyntheticWindow(uint64_t seed) : loss(1.0) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n01;
    speed_biases.assign(frames, std::vector<double>(kSpeedBiasSize));
    for (int k = 0; k < frames; ++k) {
      poses.push_back(Pose(Eigen::Vector3d(0.3 * k, 0.1 * std::sin(k), 0.05 * k),
                           ExpQ(Eigen::Vector3d(0.02 * k, -0.03 * k, 0.1 + 0.2 * k))));
      for (double& x : speed_biases[k]) x = 0.1 * n01(rng);
    }
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
    const Eigen::Isometry3d T_BC = Eigen::Isometry3d::Identity();
    inv_depths.resize(tracks);
    track_terms.resize(tracks);
    for (int i = 0; i < tracks; ++i) {
      const Eigen::Vector3d l_W(-1.0 + 0.25 * i, 0.4 * std::cos(i), 3.0 + 0.3 * i);
      const int anchor = i % 2;
      const Eigen::Vector3d p_C =
          PoseQ(poses[anchor].data()).conjugate() * (l_W - PoseP(poses[anchor].data()));
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
    prior.r.resize(prior_columns);
    for (int i = 0; i < prior_columns; ++i) prior.r[i] = n01(rng);
    prior.H = prior.J.transpose() * prior.J;
    prior.g = prior.J.transpose() * prior.r;
    for (int k = 0; k < frames; ++k) {
      pose_blocks.push_back(poses[k].data());
      speed_bias_blocks.push_back(speed_biases[k].data());
    }
  }
  SyntheticWindow(const SyntheticWindow&) = delete;
  SyntheticWindow& operator=(const SyntheticWindow&) = delete;

  std::vector<std::vector<double>> poses, speed_biases;
  std::vector<double*> pose_blocks, speed_bias_blocks;
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  std::vector<MarginalizationTerm> terms;  // the two-frame factors
  ceres::CauchyLoss loss;
  std::vector<double> inv_depths;
  std::vector<std::vector<WindowInformation::Reprojection>> track_terms;  // per track
  std::vector<std::unique_ptr<ReprojectionFactor>> factors;
  DroppedBlocks dropped;                                // the inverse depths
  std::vector<MarginalizationTerm> reprojection_terms;  // every reprojection, with the loss
  LinearPrior prior;
};

}  // namespace vigil::estimator::testing
