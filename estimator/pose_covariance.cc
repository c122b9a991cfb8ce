#include "estimator/pose_covariance.h"

#include <Eigen/Cholesky>

namespace vigil::estimator {
namespace {

// The row of the world yaw of a pose in its tangent: delta yaw = e_z^T R_WB delta theta_B.
Eigen::RowVector3d YawRow(const Eigen::Quaterniond& q_WB) {
  return Eigen::Vector3d::UnitZ().transpose() * q_WB.toRotationMatrix();
}

}  // namespace

bool GaugeFixedCovariance(const Eigen::MatrixXd& H, int oldest_column, const Eigen::Quaterniond& q_WB_oldest,
                          int newest_column, Matrix6d* covariance) {
  Eigen::MatrixXd conditioned = H;
  conditioned.block<3, 3>(oldest_column, oldest_column) += kGaugeInformation * Eigen::Matrix3d::Identity();
  const Eigen::RowVector3d yaw = YawRow(q_WB_oldest);
  conditioned.block<3, 3>(oldest_column + 3, oldest_column + 3) += kGaugeInformation * yaw.transpose() * yaw;
  const Eigen::LLT<Eigen::MatrixXd> llt(conditioned);
  if (llt.info() != Eigen::Success) return false;
  // The newest block of the inverse: solve for the six unit vectors of its columns only.
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(H.rows(), 6);
  unit.block<6, 6>(newest_column, 0).setIdentity();
  const Eigen::MatrixXd columns = llt.solve(unit);
  const Matrix6d block = columns.block<6, 6>(newest_column, 0);
  *covariance = 0.5 * (block + block.transpose());
  return covariance->allFinite();
}

Matrix6d ChainGaugeCovariance(const Matrix6d& relative, const Matrix6d& oldest_global,
                              const Eigen::Vector3d& p_W_oldest, const Eigen::Quaterniond& q_WB_oldest,
                              const Eigen::Vector3d& p_W_newest, const Eigen::Quaterniond& q_WB_newest) {
  Eigen::Matrix<double, 4, 6> A = Eigen::Matrix<double, 4, 6>::Zero();
  A.topLeftCorner<3, 3>().setIdentity();
  A.block<1, 3>(3, 3) = YawRow(q_WB_oldest);
  Eigen::Matrix<double, 6, 4> G = Eigen::Matrix<double, 6, 4>::Zero();
  G.topLeftCorner<3, 3>().setIdentity();
  G.block<3, 1>(0, 3) = Eigen::Vector3d::UnitZ().cross(p_W_newest - p_W_oldest);
  G.block<3, 1>(3, 3) = q_WB_newest.toRotationMatrix().transpose() * Eigen::Vector3d::UnitZ();
  const Eigen::Matrix4d gauge = A * oldest_global * A.transpose();
  return relative + G * gauge * G.transpose();
}

}  // namespace vigil::estimator
