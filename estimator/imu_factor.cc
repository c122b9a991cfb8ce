#include "estimator/imu_factor.h"

#include "core/so3.h"

namespace vigil::estimator {

ImuFactor::ImuFactor(const Preintegration& pre, const Eigen::Vector3d& g_W) : pre_(pre), g_W_(g_W) {}

bool ImuFactor::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  const Vector3d p_i = PoseP(parameters[0]);
  const Eigen::Quaterniond q_i = PoseQ(parameters[0]).normalized();
  const Eigen::Map<const Vector3d> v_i(parameters[1]), ba_i(parameters[1] + 3), bg_i(parameters[1] + 6);
  const Vector3d p_j = PoseP(parameters[2]);
  const Eigen::Quaterniond q_j = PoseQ(parameters[2]).normalized();
  const Eigen::Map<const Vector3d> v_j(parameters[3]), ba_j(parameters[3] + 3), bg_j(parameters[3] + 6);

  const double T = pre_.sum_dt_s();
  // The whitening, with a gated factor's inflation folded in (an unscaled factor uses the cached matrix).
  Matrix15d scaled_sqrt_information;
  if (weight_ != 1.0) scaled_sqrt_information = weight_ * pre_.sqrt_information();
  const Matrix15d& sqrt_information = weight_ != 1.0 ? scaled_sqrt_information : pre_.sqrt_information();
  const Matrix3d Ri_T = q_i.toRotationMatrix().transpose();
  const Vector3d dp_W = p_j - p_i - v_i * T - 0.5 * g_W_ * T * T;
  const Vector3d dv_W = v_j - v_i - g_W_ * T;
  const Eigen::Quaterniond gamma = pre_.CorrectedDeltaQ(bg_i);
  const Eigen::Quaterniond q_ij = q_i.conjugate() * q_j;
  const Eigen::Quaterniond err = gamma.conjugate() * q_ij;

  Eigen::Map<Eigen::Matrix<double, 15, 1>> r(residuals);
  r.segment<3>(kDp) = Ri_T * dp_W - pre_.CorrectedDeltaP(ba_i, bg_i);
  r.segment<3>(kDtheta) = 2.0 * err.vec();
  r.segment<3>(kDv) = Ri_T * dv_W - pre_.CorrectedDeltaV(ba_i, bg_i);
  r.segment<3>(kBa) = ba_j - ba_i;
  r.segment<3>(kBg) = bg_j - bg_i;
  r = sqrt_information * r;
  if (jacobians == nullptr) return true;

  const Matrix15d& J = pre_.jacobian();
  const Vector3d dbg = bg_i - pre_.linearized_b_g();
  const Matrix3d dq_dbg = RightJacobian(J.block<3, 3>(kDtheta, kBg) * dbg) * J.block<3, 3>(kDtheta, kBg);
  // Each Jacobian block is whitened 3x3 block by 3x3 block: S (upper triangular) times the unwhitened block
  // is the sum over its nonzero 3x3 blocks (residual rows r) of S's columns r..r+2 times that block. The
  // comment above each block names its nonzero unwhitened blocks d r_x / d x (the residual of imu_factor.h;
  // ()_33: lower right 3x3 block of a quaternion product matrix, J_x,y: preintegration Jacobian blocks).
  auto S = [&](int residual_row) { return sqrt_information.middleCols<3>(residual_row); };
  using RowMajor15x7 = Eigen::Matrix<double, 15, 7, Eigen::RowMajor>;
  using RowMajor15x9 = Eigen::Matrix<double, 15, 9, Eigen::RowMajor>;
  if (jacobians[0] != nullptr) {  // pose_i: [delta p, delta theta]
    Eigen::Map<RowMajor15x7> jac(jacobians[0]);
    // d r_p / d p_i = -R_i^T (r_q, r_v, r_ba, r_bg do not depend on p_i)
    jac.leftCols<3>() = S(kDp) * -Ri_T;
    // d r_p / d theta_i = [R_i^T dp_W]x, d r_q / d theta_i = -(L(gamma^-1) R(q_ij))_33, d r_v / d theta_i =
    // [R_i^T dv_W]x (bias rows: 0)
    jac.middleCols<3>(3) =
        S(kDp) * Skew(Ri_T * dp_W) +
        S(kDtheta) * -(QuatLeft(gamma.conjugate()) * QuatRight(q_ij)).bottomRightCorner<3, 3>() +
        S(kDv) * Skew(Ri_T * dv_W);
    jac.col(6).setZero();
  }
  if (jacobians[1] != nullptr) {  // speed_bias_i: [v, b_a, b_g]
    Eigen::Map<RowMajor15x9> jac(jacobians[1]);
    // d r_p / d v_i = -T R_i^T, d r_v / d v_i = -R_i^T
    jac.leftCols<3>() = S(kDp) * (-T * Ri_T) + S(kDv) * -Ri_T;
    // d r_p / d b_a,i = -J_p,ba, d r_v / d b_a,i = -J_v,ba, d r_ba / d b_a,i = -I
    jac.middleCols<3>(3) = S(kDp) * -J.block<3, 3>(kDp, kBa) + S(kDv) * -J.block<3, 3>(kDv, kBa) - S(kBa);
    // d r_p / d b_g,i = -J_p,bg, d r_q / d b_g,i = -R(err)_33 Jr J_q,bg, d r_v / d b_g,i = -J_v,bg,
    // d r_bg / d b_g,i = -I
    jac.rightCols<3>() = S(kDp) * -J.block<3, 3>(kDp, kBg) +
                         S(kDtheta) * -(QuatRight(err).bottomRightCorner<3, 3>() * dq_dbg) +
                         S(kDv) * -J.block<3, 3>(kDv, kBg) - S(kBg);
  }
  if (jacobians[2] != nullptr) {  // pose_j
    Eigen::Map<RowMajor15x7> jac(jacobians[2]);
    // d r_p / d p_j = R_i^T
    jac.leftCols<3>() = S(kDp) * Ri_T;
    // d r_q / d theta_j = L(err)_33 (the lower right 3x3 block of err's left-multiplication matrix)
    jac.middleCols<3>(3) = S(kDtheta) * QuatLeft(err).bottomRightCorner<3, 3>();
    jac.col(6).setZero();
  }
  if (jacobians[3] != nullptr) {  // speed_bias_j
    Eigen::Map<RowMajor15x9> jac(jacobians[3]);
    // d r_v / d v_j = R_i^T
    jac.leftCols<3>() = S(kDv) * Ri_T;
    // d r_ba / d b_a,j = I
    jac.middleCols<3>(3) = S(kBa);
    // d r_bg / d b_g,j = I
    jac.rightCols<3>() = S(kBg);
  }
  return true;
}

}  // namespace vigil::estimator
