#include "estimator/preintegration.h"

#include <cmath>

#include <Eigen/Cholesky>

#include "core/so3.h"

namespace vigil::estimator {

Preintegration::Preintegration(const Eigen::Vector3d& a0_B, const Eigen::Vector3d& w0_B,
                               const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g,
                               const ImuNoiseDensities& noise, double imu_rate_hz,
                               double first_variance_scale)
    : a0_B_(a0_B),
      w0_B_(w0_B),
      b_a_(b_a),
      b_g_(b_g),
      noise_(noise),
      imu_rate_hz_(imu_rate_hz),
      first_variance_scale_(first_variance_scale) {
  // Per-sample white-noise variances sigma_d^2 = sigma_c^2 * rate, doubled: each sample is shared by two
  // midpoint steps, and steps are propagated as independent, so each half-weighted sample of a step carries
  // twice the variance; the sum over many steps then has the spread of the real, shared samples.
  const double var_a = 2.0 * noise.accel_noise_density * noise.accel_noise_density * imu_rate_hz;
  const double var_g = 2.0 * noise.gyro_noise_density * noise.gyro_noise_density * imu_rate_hz;
  noise_var_ << var_a, var_a, var_a, var_g, var_g, var_g, var_a, var_a, var_a, var_g, var_g, var_g;
  Reset();
}

void Preintegration::Reset() {
  last_a_B_ = a0_B_;
  last_w_B_ = w0_B_;
  last_variance_scale_ = first_variance_scale_;
  sum_dt_s_ = 0.0;
  delta_p_.setZero();
  delta_v_.setZero();
  delta_q_.setIdentity();
  jacobian_.setIdentity();
  covariance_.setZero();
  sqrt_information_.reset();
}

void Preintegration::Push(double dt_s, const Eigen::Vector3d& a_B, const Eigen::Vector3d& w_B,
                          double variance_scale) {
  steps_.push_back({dt_s, a_B, w_B, variance_scale});
  Integrate(dt_s, a_B, w_B, variance_scale);
}

void Preintegration::Repropagate(const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g) {
  b_a_ = b_a;
  b_g_ = b_g;
  Reset();
  for (const Step& s : steps_) Integrate(s.dt_s, s.a_B, s.w_B, s.variance_scale);
}

void Preintegration::Integrate(double dt, const Eigen::Vector3d& a1_B, const Eigen::Vector3d& w1_B,
                               double variance_scale1) {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  const Vector3d w_mid = 0.5 * (last_w_B_ + w1_B) - b_g_;
  const Vector3d phi = w_mid * dt;
  const Eigen::Quaterniond q_step = ExpQ(phi);
  const Matrix3d R_step = q_step.toRotationMatrix();
  const Matrix3d Jr = RightJacobian(phi);
  const Matrix3d R0 = delta_q_.toRotationMatrix();
  const Eigen::Quaterniond q1 = (delta_q_ * q_step).normalized();
  const Matrix3d R1 = q1.toRotationMatrix();

  const Vector3d a0_un = last_a_B_ - b_a_;
  const Vector3d a1_un = a1_B - b_a_;
  const Vector3d acc_mid = 0.5 * (R0 * a0_un + R1 * a1_un);

  // Partial derivatives of the midpoint acceleration (in B_i) of this step.
  const Matrix3d a0_x = Skew(a0_un);
  const Matrix3d a1_x = Skew(a1_un);
  const Matrix3d dacc_dtheta = -0.5 * (R0 * a0_x + R1 * a1_x * R_step.transpose());
  const Matrix3d dacc_dba = -0.5 * (R0 + R1);
  const Matrix3d dacc_dwmid = -0.5 * R1 * a1_x * Jr * dt;  // through R1 = R0 Exp(w_mid dt)

  // Transition F = I + N of the error state [dp, dtheta, dv, b_a, b_g]: only the first nine rows of N are
  // non-zero (the biases are constant within a step), so F J = J + [N9 J; 0] and F P F^T = M + [M N9^T, 0]
  // with M = F P -- a third of the flops of the dense products.
  Eigen::Matrix<double, 9, 15> N9 = Eigen::Matrix<double, 9, 15>::Zero();
  N9.block<3, 3>(kDp, kDtheta) = 0.5 * dt * dt * dacc_dtheta;
  N9.block<3, 3>(kDp, kDv) = Matrix3d::Identity() * dt;
  N9.block<3, 3>(kDp, kBa) = 0.5 * dt * dt * dacc_dba;
  N9.block<3, 3>(kDp, kBg) = -0.5 * dt * dt * dacc_dwmid;
  N9.block<3, 3>(kDtheta, kDtheta) = R_step.transpose() - Matrix3d::Identity();
  N9.block<3, 3>(kDtheta, kBg) = -Jr * dt;
  N9.block<3, 3>(kDv, kDtheta) = dt * dacc_dtheta;
  N9.block<3, 3>(kDv, kBa) = dt * dacc_dba;
  N9.block<3, 3>(kDv, kBg) = -dt * dacc_dwmid;

  // Noise input [n_a0, n_g0, n_a1, n_g1] into the first nine rows (G9); noise on a measurement acts like
  // minus a bias change on that sample alone, each gyro sample carries half of w_mid. The bias random walks
  // enter the bias rows directly.
  Eigen::Matrix<double, 9, 12> G9 = Eigen::Matrix<double, 9, 12>::Zero();
  const Matrix3d dacc_dna0 = 0.5 * R0;
  const Matrix3d dacc_dna1 = 0.5 * R1;
  const Matrix3d dacc_dng = 0.5 * dacc_dwmid;
  G9.block<3, 3>(kDp, 0) = 0.5 * dt * dt * dacc_dna0;
  G9.block<3, 3>(kDp, 3) = 0.5 * dt * dt * dacc_dng;
  G9.block<3, 3>(kDp, 6) = 0.5 * dt * dt * dacc_dna1;
  G9.block<3, 3>(kDp, 9) = 0.5 * dt * dt * dacc_dng;
  G9.block<3, 3>(kDtheta, 3) = 0.5 * Jr * dt;
  G9.block<3, 3>(kDtheta, 9) = 0.5 * Jr * dt;
  G9.block<3, 3>(kDv, 0) = dt * dacc_dna0;
  G9.block<3, 3>(kDv, 3) = dt * dacc_dng;
  G9.block<3, 3>(kDv, 6) = dt * dacc_dna1;
  G9.block<3, 3>(kDv, 9) = dt * dacc_dng;

  // The first three columns of N9 (d/d delta p) are zero as well.
  const auto N9r = N9.rightCols<12>();
  jacobian_.topRows<9>() += N9r * jacobian_.bottomRows<12>();
  Matrix15d M = covariance_;
  M.topRows<9>() += N9r * covariance_.bottomRows<12>();
  covariance_ = M;
  covariance_.leftCols<9>() += M.rightCols<12>() * N9r.transpose();
  if (last_variance_scale_ == 1.0 && variance_scale1 == 1.0) {
    covariance_.topLeftCorner<9, 9>() += G9 * noise_var_.asDiagonal() * G9.transpose();
  } else {  // untrusted samples (mitigation): [a0, w0] and [a1, w1] variances scaled per sample
    Eigen::Matrix<double, 12, 1> var = noise_var_;
    var.head<6>() *= last_variance_scale_;
    var.tail<6>() *= variance_scale1;
    covariance_.topLeftCorner<9, 9>() += G9 * var.asDiagonal() * G9.transpose();
  }
  covariance_.block<3, 3>(kBa, kBa).diagonal().array() +=
      noise_.accel_bias_random_walk * noise_.accel_bias_random_walk * dt;
  covariance_.block<3, 3>(kBg, kBg).diagonal().array() +=
      noise_.gyro_bias_random_walk * noise_.gyro_bias_random_walk * dt;

  delta_p_ += delta_v_ * dt + 0.5 * acc_mid * dt * dt;
  delta_v_ += acc_mid * dt;
  delta_q_ = q1;
  last_a_B_ = a1_B;
  last_w_B_ = w1_B;
  last_variance_scale_ = variance_scale1;
  sum_dt_s_ += dt;
  sqrt_information_.reset();
}

const Matrix15d& Preintegration::sqrt_information() const {
  if (!sqrt_information_) {
    const Matrix15d information = covariance_.inverse();
    sqrt_information_ =
        Eigen::LLT<Matrix15d>(0.5 * (information + information.transpose())).matrixL().transpose();
  }
  return *sqrt_information_;
}

Eigen::Vector3d Preintegration::CorrectedDeltaP(const Eigen::Vector3d& b_a,
                                                const Eigen::Vector3d& b_g) const {
  return delta_p_ + jacobian_.block<3, 3>(kDp, kBa) * (b_a - b_a_) +
         jacobian_.block<3, 3>(kDp, kBg) * (b_g - b_g_);
}

Eigen::Quaterniond Preintegration::CorrectedDeltaQ(const Eigen::Vector3d& b_g) const {
  return (delta_q_ * ExpQ(jacobian_.block<3, 3>(kDtheta, kBg) * (b_g - b_g_))).normalized();
}

Eigen::Vector3d Preintegration::CorrectedDeltaV(const Eigen::Vector3d& b_a,
                                                const Eigen::Vector3d& b_g) const {
  return delta_v_ + jacobian_.block<3, 3>(kDv, kBa) * (b_a - b_a_) +
         jacobian_.block<3, 3>(kDv, kBg) * (b_g - b_g_);
}

}  // namespace vigil::estimator
