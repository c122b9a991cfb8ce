// IMU preintegration between two window frames i and j (midpoint integration).
//
// The deltas are expressed in the body frame of frame i and do not depend on the state at i:
//   delta_p = sum of 1/2 a dt^2 + delta_v dt,  delta_q = R_{B_i B_k},  delta_v = sum of a dt,
// where a is the bias-corrected specific force rotated into B_i, averaged over each sample pair (midpoint).
//
// Error-state order everywhere: [delta p (0..2), delta theta (3..5), delta v (6..8), b_a (9..11), b_g
// (12..14)], with the rotation error on the right: delta_q_true = delta_q * Exp(delta theta).
//
// jacobian() is d(state at j) / d(state at i) of the discrete propagation, accumulated step by step; its bias
// columns (9..14) give the first-order bias correction of the deltas (CorrectedDelta*).
//
// Noise discretization (documented contract, the same convention the simulator uses to generate noise):
// the continuous white-noise densities sigma_c [unit/sqrt(Hz)] become per-sample standard deviations
// sigma_d = sigma_c * sqrt(imu_rate_hz) (= sigma_c / sqrt(dt) at the nominal period); the bias random walks
// sigma_w [unit/s/sqrt(Hz)] add a variance sigma_w^2 * dt per step of length dt. The measurement noise of
// both samples of a step enters (18-dim noise vector [n_a0, n_g0, n_a1, n_g1, n_ba, n_bg]):
//   P <- F P F^T + G Q G^T,
// with the measurement variances doubled (2 sigma_d^2): every sample is shared by two consecutive midpoint
// steps, which are propagated as independent, so the half-weighted samples of one step must carry twice the
// variance for the accumulated covariance to match the spread of real noise (checked by a Monte Carlo test).
//
// In-estimator mitigation (mitigation_options.h): each sample may carry a variance scale (1 = trusted); the
// white-noise variances of a sample in the step's noise vector are multiplied by it, so an untrusted sample
// widens the covariance of every delta it enters. The scales are part of the steps and survive Repropagate()
// and merging.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "estimator/estimator_input.h"

namespace vigil::estimator {

using Matrix15d = Eigen::Matrix<double, 15, 15>;

// Offsets of the error-state blocks.
inline constexpr int kDp = 0;
inline constexpr int kDtheta = 3;
inline constexpr int kDv = 6;
inline constexpr int kBa = 9;
inline constexpr int kBg = 12;

class Preintegration {
 public:
  // One raw IMU step pushed after the first sample.
  struct Step {
    double dt_s = 0.0;
    Eigen::Vector3d a_B = Eigen::Vector3d::Zero();
    Eigen::Vector3d w_B = Eigen::Vector3d::Zero();
    double variance_scale = 1.0;  // of the sample at the end of the step
  };

  // a0_B / w0_B: the IMU sample at frame i (or interpolated to its time); b_a / b_g: the bias linearization
  // point; first_variance_scale: the first sample's variance scale.
  Preintegration(const Eigen::Vector3d& a0_B, const Eigen::Vector3d& w0_B, const Eigen::Vector3d& b_a,
                 const Eigen::Vector3d& b_g, const ImuNoiseDensities& noise, double imu_rate_hz,
                 double first_variance_scale = 1.0);

  // Integrates from the last sample to (a_B, w_B), dt_s later, with the midpoint rule; `variance_scale`
  // multiplies the new sample's white-noise variances.
  void Push(double dt_s, const Eigen::Vector3d& a_B, const Eigen::Vector3d& w_B, double variance_scale = 1.0);
  // Re-integrates every pushed step with a new bias linearization point.
  void Repropagate(const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g);

  double sum_dt_s() const { return sum_dt_s_; }
  const Eigen::Vector3d& delta_p() const { return delta_p_; }
  const Eigen::Quaterniond& delta_q() const { return delta_q_; }
  const Eigen::Vector3d& delta_v() const { return delta_v_; }
  const Matrix15d& jacobian() const { return jacobian_; }
  const Matrix15d& covariance() const { return covariance_; }
  // Upper-triangular S with S^T S = covariance^-1 (whitens an IMU residual); computed once per change of the
  // deltas, since every frame's window problem builds a factor from each preintegration.
  const Matrix15d& sqrt_information() const;
  const Eigen::Vector3d& linearized_b_a() const { return b_a_; }
  const Eigen::Vector3d& linearized_b_g() const { return b_g_; }
  // The first sample and every pushed step (to merge two preintegrations or replay them).
  const Eigen::Vector3d& first_a_B() const { return a0_B_; }
  const Eigen::Vector3d& first_w_B() const { return w0_B_; }
  const std::vector<Step>& steps() const { return steps_; }
  const ImuNoiseDensities& noise() const { return noise_; }
  double imu_rate_hz() const { return imu_rate_hz_; }

  // First-order bias-corrected deltas for new bias estimates.
  Eigen::Vector3d CorrectedDeltaP(const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g) const;
  Eigen::Quaterniond CorrectedDeltaQ(const Eigen::Vector3d& b_g) const;
  Eigen::Quaterniond CorrectedDeltaQ(const Eigen::Vector3d& /*b_a*/, const Eigen::Vector3d& b_g) const {
    return CorrectedDeltaQ(b_g);
  }
  Eigen::Vector3d CorrectedDeltaV(const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g) const;

 private:
  void Reset();
  void Integrate(double dt_s, const Eigen::Vector3d& a1_B, const Eigen::Vector3d& w1_B,
                 double variance_scale1);

  // Inputs.
  Eigen::Vector3d a0_B_, w0_B_;
  Eigen::Vector3d b_a_, b_g_;
  ImuNoiseDensities noise_;
  double imu_rate_hz_;
  double first_variance_scale_;
  std::vector<Step> steps_;
  Eigen::Matrix<double, 12, 1>
      noise_var_;  // per-sample variances of [a0, w0, a1, w1] (the bias walks scale with dt)

  // Integration state.
  Eigen::Vector3d last_a_B_, last_w_B_;
  double last_variance_scale_ = 1.0;
  double sum_dt_s_ = 0.0;
  Eigen::Vector3d delta_p_, delta_v_;
  Eigen::Quaterniond delta_q_;
  Matrix15d jacobian_, covariance_;
  mutable std::optional<Matrix15d> sqrt_information_;  // cache, cleared by Reset() and Integrate()
};

}  // namespace vigil::estimator
