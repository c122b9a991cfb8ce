// The initial bias prior: what marginalization makes of it, and that the estimator keeps it through the run.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "core/interpolation.h"
#include "estimator/bias_prior_factor.h"
#include "estimator/imu_factor.h"
#include "estimator/marginalization.h"
#include "estimator/run_estimator.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// Marginalizing frame i (pose, speed, biases) of [bias prior on i, IMU factor i -> j] leaves a prior on frame
// j's biases with variance prior^2 + random walk^2 * T: the pose and velocity rows of the IMU factor are
// absorbed by frame i's free pose and velocity, only the bias walk rows carry the prior over.
TEST(BiasPriorTest, MarginalizationCarriesThePriorToTheNextFrame) {
  ImuNoiseDensities noise;
  noise.accel_bias_random_walk = 1e-2;  // large, so that the walk term is visible
  noise.gyro_bias_random_walk = 1e-3;
  Preintegration pre(Eigen::Vector3d(0.2, -0.1, 9.7), Eigen::Vector3d(0.3, 0.1, -0.2),
                     Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), noise, 200.0);
  for (int k = 1; k <= 40; ++k)
    pre.Push(0.005, Eigen::Vector3d(0.2 + 0.01 * k, -0.1, 9.7), Eigen::Vector3d(0.3, 0.1 - 0.002 * k, -0.2));
  const double T = pre.sum_dt_s();

  std::vector<double> pose_i = {0, 0, 0, 0, 0, 0, 1}, pose_j = {0.1, 0.2, 0.0, 0, 0, 0.1, 0.995};
  std::vector<double> sb_i = {0.5, 0.1, 0, 0, 0, 0, 0, 0, 0}, sb_j = {0.5, 0.1, 0, 0, 0, 0, 0, 0, 0};
  const double accel_std = 0.1, gyro_std = 0.01;
  const BiasPriorFactor bias_prior(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), accel_std, gyro_std);
  const ImuFactor imu(pre, Eigen::Vector3d(0, 0, -9.81));
  const std::vector<MarginalizationTerm> terms = {
      {&bias_prior, nullptr, {sb_i.data()}},
      {&imu, nullptr, {pose_i.data(), sb_i.data(), pose_j.data(), sb_j.data()}}};
  LinearPrior prior;
  const double ridge = 1e-8;
  ASSERT_TRUE(Marginalize(nullptr, terms, {pose_i.data(), sb_i.data()}, ridge, &prior));
  ASSERT_EQ(prior.blocks.size(), 2u);
  ASSERT_EQ(prior.blocks[1].address, sb_j.data());
  const Eigen::MatrixXd S = prior.J.transpose() * prior.J - ridge * Eigen::MatrixXd::Identity(15, 15);
  const double expected_a =
      1.0 / (accel_std * accel_std + noise.accel_bias_random_walk * noise.accel_bias_random_walk * T);
  const double expected_g =
      1.0 / (gyro_std * gyro_std + noise.gyro_bias_random_walk * noise.gyro_bias_random_walk * T);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(S(9 + k, 9 + k), expected_a, 1e-6 * expected_a);
    EXPECT_NEAR(S(12 + k, 12 + k), expected_g, 1e-6 * expected_g);
  }
  // Nothing about frame j's pose and velocity (position and yaw stay free: the gauge is untouched) ...
  EXPECT_LT(S.topLeftCorner(9, 9).cwiseAbs().maxCoeff(), 1e-6);
  // ... and the biases are uncorrelated with them.
  EXPECT_LT(S.block(0, 9, 9, 6).cwiseAbs().maxCoeff(), 1e-6);
}

// Largest accelerometer-bias error of a run's states against the ground truth.
double WorstAccelBiasError(const EstimatorResult& result, const std::vector<NavState>& groundtruth) {
  double worst = 0.0;
  for (const NavState& s : result.states) {
    NavState truth;
    if (InterpolateNavState(groundtruth, s.t_ns, &truth)) worst = std::max(worst, (s.b_a - truth.b_a).norm());
  }
  return worst;
}

// With ground-truth initialization the prior is centred on the true biases: a tight prior pins the estimated
// accelerometer bias to the truth for the whole run, long after the frame it was put on left the window (so
// it was carried by the marginalization prior); without it the bias wanders with the window's noise.
TEST(BiasPriorTest, TightPriorHoldsTheBiasThroughTheRun) {
  sim::SimOptions sim_options;
  sim_options.duration_s = 5.0;
  sim_options.imu.noise.initial_accel_bias = {0.05, -0.03, 0.08};  // the prior must follow the initializer
  const Dataset data = sim::Simulate(sim_options, 5);
  const EstimatorInput input = testing::InputFromSimulation(sim_options, data, 5);

  // A short window with frequent keyframes, so that the prior's frame leaves it early in the 5 s run.
  EstimatorOptions short_window;
  short_window.window.size = 10;
  short_window.window.min_parallax_px = 10.0;
  EstimatorOptions tight = short_window;
  tight.prior.accel_bias_std = 1e-3;
  const EstimatorResult with_prior = RunEstimator(tight, input);
  ASSERT_TRUE(with_prior.ok) << with_prior.failure_reason;
  EXPECT_GT(with_prior.keyframes, 2 * tight.window.size);  // the prior's frame left the window long ago

  EstimatorOptions off = short_window;
  off.prior.accel_bias_std = 0.0;
  off.prior.gyro_bias_std = 0.0;
  const EstimatorResult without_prior = RunEstimator(off, input);
  ASSERT_TRUE(without_prior.ok) << without_prior.failure_reason;

  const double err_with = WorstAccelBiasError(with_prior, data.groundtruth);
  const double err_without = WorstAccelBiasError(without_prior, data.groundtruth);
  std::printf("worst |b_a error|: tight prior %.4f, no prior %.4f m/s^2\n", err_with, err_without);
  EXPECT_LT(err_with, 5e-3);
  EXPECT_GT(err_without, 2.0 * err_with);
}

}  // namespace
}  // namespace vigil::estimator
