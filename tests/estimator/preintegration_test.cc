#include "estimator/preintegration.h"

#include <vector>

#include <gtest/gtest.h>

#include "core/random.h"
#include "core/so3.h"
#include "sim/simulator.h"

namespace vigil::estimator {
namespace {

constexpr double kRateHz = 200.0;

struct Samples {
  std::vector<Eigen::Vector3d> a_B, w_B;
};

// A vigorous but smooth random IMU sequence (rotating at up to ~1 rad/s, accelerating around +g on z).
Samples RandomSamples(int n, uint64_t seed) {
  Rng rng(seed, "preintegration_test");
  Samples s;
  Eigen::Vector3d a(0.3, -0.2, 9.81), w(0.4, -0.3, 0.8);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) {
      a[i] += rng.Normal(0.0, 0.3);
      w[i] += rng.Normal(0.0, 0.05);
    }
    s.a_B.push_back(a);
    s.w_B.push_back(w);
  }
  return s;
}

Preintegration Integrate(const Samples& s, const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g,
                         const ImuNoiseDensities& noise = {}) {
  Preintegration pre(s.a_B[0], s.w_B[0], b_a, b_g, noise, kRateHz);
  for (std::size_t k = 1; k < s.a_B.size(); ++k) pre.Push(1.0 / kRateHz, s.a_B[k], s.w_B[k]);
  return pre;
}

// [delta p, delta theta, delta v] of `b` relative to `a` in the error-state convention.
Eigen::Matrix<double, 9, 1> Difference(const Preintegration& b, const Preintegration& a) {
  Eigen::Matrix<double, 9, 1> d;
  d.segment<3>(kDp) = b.delta_p() - a.delta_p();
  d.segment<3>(kDtheta) = LogQ(a.delta_q().conjugate() * b.delta_q());
  d.segment<3>(kDv) = b.delta_v() - a.delta_v();
  return d;
}

TEST(PreintegrationTest, BiasJacobianMatchesCentralDifferences) {
  const Samples s = RandomSamples(41, 1);
  const Eigen::Vector3d b_a(0.05, -0.1, 0.2), b_g(0.01, 0.02, -0.03);
  const Preintegration pre = Integrate(s, b_a, b_g);
  const double h = 1e-6;
  for (int col = 0; col < 6; ++col) {
    Eigen::Matrix<double, 6, 1> step = Eigen::Matrix<double, 6, 1>::Zero();
    step[col] = h;
    Preintegration plus = pre, minus = pre;
    plus.Repropagate(b_a + step.head<3>(), b_g + step.tail<3>());
    minus.Repropagate(b_a - step.head<3>(), b_g - step.tail<3>());
    const Eigen::Matrix<double, 9, 1> numeric = (Difference(plus, pre) - Difference(minus, pre)) / (2.0 * h);
    const Eigen::Matrix<double, 9, 1> analytic = pre.jacobian().block<9, 1>(0, kBa + col);
    EXPECT_LT((numeric - analytic).norm(), 1e-6 * (1.0 + analytic.norm())) << "bias column " << col << "\n"
                                                                           << numeric.transpose() << "\n"
                                                                           << analytic.transpose();
  }
}

// The state columns: propagating from a perturbed start equals J times the perturbation. A preintegration
// always starts at identity, so split the sequence: integrate the second half from the end of the first one
// by composing deltas, and compare with the chain of the two Jacobians.
TEST(PreintegrationTest, JacobianComposesOverSplitIntervals) {
  const Samples s = RandomSamples(60, 2);
  const Eigen::Vector3d b_a(0.1, 0.0, -0.1), b_g(-0.02, 0.01, 0.0);
  Samples first, second;
  first.a_B.assign(s.a_B.begin(), s.a_B.begin() + 30);
  first.w_B.assign(s.w_B.begin(), s.w_B.begin() + 30);
  second.a_B.assign(s.a_B.begin() + 29, s.a_B.end());
  second.w_B.assign(s.w_B.begin() + 29, s.w_B.end());
  const Preintegration whole = Integrate(s, b_a, b_g);
  const Preintegration p1 = Integrate(first, b_a, b_g);
  const Preintegration p2 = Integrate(second, b_a, b_g);
  // Composition of the deltas.
  const double T2 = p2.sum_dt_s();
  EXPECT_NEAR(whole.sum_dt_s(), p1.sum_dt_s() + T2, 1e-12);
  EXPECT_LT((whole.delta_p() - (p1.delta_p() + p1.delta_v() * T2 + p1.delta_q() * p2.delta_p())).norm(),
            1e-9);
  EXPECT_LT((whole.delta_v() - (p1.delta_v() + p1.delta_q() * p2.delta_v())).norm(), 1e-9);
  EXPECT_LT(AngleOf(whole.delta_q().conjugate() * (p1.delta_q() * p2.delta_q())), 1e-9);
  // The Jacobian of the composition: [p, theta, v] of the second part depend on the first's as
  // dp = dp1 + dv1 T2 - R1 [dp2]x dtheta1, dtheta = R2^T dtheta1, dv = dv1 - R1 [dv2]x dtheta1, plus bias
  // terms.
  Matrix15d chain = Matrix15d::Identity();
  const Eigen::Matrix3d R1 = p1.delta_q().toRotationMatrix();
  chain.block<3, 3>(kDp, kDtheta) = -R1 * Skew(p2.delta_p());
  chain.block<3, 3>(kDp, kDv) = Eigen::Matrix3d::Identity() * T2;
  chain.block<3, 3>(kDtheta, kDtheta) = p2.delta_q().toRotationMatrix().transpose();
  chain.block<3, 3>(kDv, kDtheta) = -R1 * Skew(p2.delta_v());
  chain.block<3, 6>(kDp, kBa) = R1 * p2.jacobian().block<3, 6>(kDp, kBa);
  chain.block<3, 6>(kDtheta, kBa) = p2.jacobian().block<3, 6>(kDtheta, kBa);
  chain.block<3, 6>(kDv, kBa) = R1 * p2.jacobian().block<3, 6>(kDv, kBa);
  const Matrix15d expected = chain * p1.jacobian();
  EXPECT_LT((whole.jacobian() - expected).norm(), 1e-9 * expected.norm());
}

TEST(PreintegrationTest, FirstOrderBiasCorrectionApproximatesRepropagation) {
  const Samples s = RandomSamples(21, 3);
  const Eigen::Vector3d b_a(0.0, 0.0, 0.0), b_g(0.0, 0.0, 0.0);
  const Preintegration pre = Integrate(s, b_a, b_g);
  const Eigen::Vector3d new_b_a(0.05, -0.03, 0.02), new_b_g(0.004, -0.003, 0.005);
  Preintegration exact = pre;
  exact.Repropagate(new_b_a, new_b_g);
  // Without correction the deltas are off by O(|db|); with it, by O(|db|^2).
  const double dp_raw = (pre.delta_p() - exact.delta_p()).norm();
  const double dp_corrected = (pre.CorrectedDeltaP(new_b_a, new_b_g) - exact.delta_p()).norm();
  const double dv_raw = (pre.delta_v() - exact.delta_v()).norm();
  const double dv_corrected = (pre.CorrectedDeltaV(new_b_a, new_b_g) - exact.delta_v()).norm();
  const double dq_raw = AngleOf(pre.delta_q().conjugate() * exact.delta_q());
  const double dq_corrected = AngleOf(pre.CorrectedDeltaQ(new_b_a, new_b_g).conjugate() * exact.delta_q());
  EXPECT_GT(dp_raw, 1e-4);
  EXPECT_LT(dp_corrected, 1e-2 * dp_raw);
  EXPECT_LT(dv_corrected, 1e-2 * dv_raw);
  EXPECT_LT(dq_corrected, 1e-2 * dq_raw);
  EXPECT_EQ(exact.linearized_b_a(), new_b_a);
  EXPECT_EQ(exact.linearized_b_g(), new_b_g);
}

// Deltas of an ideal IMU match the ground-truth motion between two frames of the simulator's ellipse.
TEST(PreintegrationTest, IdealImuDeltasMatchGroundTruth) {
  sim::SimOptions options;
  options.duration_s = 3.0;
  options.imu.noise.enabled = false;
  const Dataset data = sim::Simulate(options, 7);
  ASSERT_EQ(data.imu.size(), data.groundtruth.size());
  const Eigen::Vector3d g_W(0.0, 0.0, -options.gravity_mps2);
  for (const std::size_t i : {0, 100, 370}) {
    const std::size_t j = i + 60;  // 0.3 s, about nine camera frames
    Preintegration pre(data.imu[i].a_B, data.imu[i].w_B, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), {},
                       options.imu.rate_hz);
    for (std::size_t k = i + 1; k <= j; ++k)
      pre.Push(NsToS(data.imu[k].t_ns - data.imu[k - 1].t_ns), data.imu[k].a_B, data.imu[k].w_B);
    const NavState& si = data.groundtruth[i];
    const NavState& sj = data.groundtruth[j];
    const double T = pre.sum_dt_s();
    EXPECT_NEAR(T, 0.3, 1e-9);
    const Eigen::Matrix3d Ri_T = si.q_WB.toRotationMatrix().transpose();
    const Eigen::Vector3d dp_true = Ri_T * (sj.p_W - si.p_W - si.v_W * T - 0.5 * g_W * T * T);
    const Eigen::Vector3d dv_true = Ri_T * (sj.v_W - si.v_W - g_W * T);
    const Eigen::Quaterniond dq_true = si.q_WB.conjugate() * sj.q_WB;
    EXPECT_LT((pre.delta_p() - dp_true).norm(), 1e-4) << "at sample " << i;
    EXPECT_LT((pre.delta_v() - dv_true).norm(), 2e-3) << "at sample " << i;
    EXPECT_LT(AngleOf(pre.delta_q().conjugate() * dq_true), 1e-4) << "at sample " << i;
    EXPECT_GT((sj.p_W - si.p_W).norm(), 0.5);  // the motion is not trivial
    EXPECT_GT(AngleOf(dq_true), 0.05);
  }
}

// The propagated covariance predicts the spread of the deltas under discrete noise drawn with the documented
// discretization (per-sample std = density * sqrt(rate)).
TEST(PreintegrationTest, CovarianceMatchesMonteCarloSpread) {
  const Samples truth = RandomSamples(21, 4);
  ImuNoiseDensities noise;
  noise.accel_noise_density = 0.02;
  noise.gyro_noise_density = 0.01;
  noise.accel_bias_random_walk = 0.0;
  noise.gyro_bias_random_walk = 0.0;
  const Preintegration nominal = Integrate(truth, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), noise);
  const double std_a = noise.accel_noise_density * std::sqrt(kRateHz);
  const double std_g = noise.gyro_noise_density * std::sqrt(kRateHz);
  Rng rng(5, "preintegration_monte_carlo");
  constexpr int kTrials = 2000;
  Eigen::Matrix<double, 9, 9> sample_cov = Eigen::Matrix<double, 9, 9>::Zero();
  for (int t = 0; t < kTrials; ++t) {
    Samples noisy = truth;
    for (std::size_t k = 0; k < noisy.a_B.size(); ++k)
      for (int i = 0; i < 3; ++i) {
        noisy.a_B[k][i] += rng.Normal(0.0, std_a);
        noisy.w_B[k][i] += rng.Normal(0.0, std_g);
      }
    const Eigen::Matrix<double, 9, 1> d =
        Difference(Integrate(noisy, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), noise), nominal);
    sample_cov += d * d.transpose() / kTrials;
  }
  const Eigen::Matrix<double, 9, 9> predicted = nominal.covariance().topLeftCorner<9, 9>();
  for (int i = 0; i < 9; ++i) {
    EXPECT_NEAR(sample_cov(i, i) / predicted(i, i), 1.0, 0.12) << "diagonal " << i;
  }
}

}  // namespace
}  // namespace vigil::estimator
