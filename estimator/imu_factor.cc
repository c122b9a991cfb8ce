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
  const Matrix15d& sqrt_information = pre_.sqrt_information();
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
  // Each block is built unwhitened over the residual rows it reaches and whitened by the matching columns of
  // the upper-triangular S: rows below the block's first nonzero row stay zero, so fixed-size products over
  // those rows and columns only replace full 15x15 products (lazy: coefficient-wise, no GEMM set-up).
  using RowMajor15x7 = Eigen::Matrix<double, 15, 7, Eigen::RowMajor>;
  using RowMajor15x9 = Eigen::Matrix<double, 15, 9, Eigen::RowMajor>;
  if (jacobians[0] != nullptr) {  // rows dp, dtheta, dv
    Eigen::Matrix<double, 9, 6> d = Eigen::Matrix<double, 9, 6>::Zero();
    d.block<3, 3>(kDp, 0) = -Ri_T;
    d.block<3, 3>(kDp, 3) = Skew(Ri_T * dp_W);
    d.block<3, 3>(kDtheta, 3) = -(QuatLeft(gamma.conjugate()) * QuatRight(q_ij)).bottomRightCorner<3, 3>();
    d.block<3, 3>(kDv, 3) = Skew(Ri_T * dv_W);
    Eigen::Map<RowMajor15x7> jac(jacobians[0]);
    jac.leftCols<6>().noalias() = sqrt_information.leftCols<9>().lazyProduct(d);
    jac.col(6).setZero();
  }
  if (jacobians[1] != nullptr) {  // all rows
    Eigen::Matrix<double, 15, 9> d = Eigen::Matrix<double, 15, 9>::Zero();
    d.block<3, 3>(kDp, 0) = -Ri_T * T;
    d.block<3, 3>(kDp, 3) = -J.block<3, 3>(kDp, kBa);
    d.block<3, 3>(kDp, 6) = -J.block<3, 3>(kDp, kBg);
    d.block<3, 3>(kDtheta, 6) = -QuatRight(err).bottomRightCorner<3, 3>() * dq_dbg;
    d.block<3, 3>(kDv, 0) = -Ri_T;
    d.block<3, 3>(kDv, 3) = -J.block<3, 3>(kDv, kBa);
    d.block<3, 3>(kDv, 6) = -J.block<3, 3>(kDv, kBg);
    d.block<3, 3>(kBa, 3) = -Matrix3d::Identity();
    d.block<3, 3>(kBg, 6) = -Matrix3d::Identity();
    Eigen::Map<RowMajor15x9>(jacobians[1]).noalias() = sqrt_information.lazyProduct(d);
  }
  if (jacobians[2] != nullptr) {  // rows dp, dtheta
    Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
    d.block<3, 3>(kDp, 0) = Ri_T;
    d.block<3, 3>(kDtheta, 3) = QuatLeft(err).bottomRightCorner<3, 3>();
    Eigen::Map<RowMajor15x7> jac(jacobians[2]);
    jac.leftCols<6>().noalias() = sqrt_information.leftCols<6>().lazyProduct(d);
    jac.col(6).setZero();
  }
  if (jacobians[3] != nullptr) {  // rows dv, b_a, b_g
    Eigen::Matrix<double, 9, 9> d = Eigen::Matrix<double, 9, 9>::Zero();
    d.block<3, 3>(0, 0) = Ri_T;
    d.block<3, 3>(3, 3) = Matrix3d::Identity();
    d.block<3, 3>(6, 6) = Matrix3d::Identity();
    Eigen::Map<RowMajor15x9>(jacobians[3]).noalias() = sqrt_information.rightCols<9>().lazyProduct(d);
  }
  return true;
}

}  // namespace vigil::estimator
