#include "estimator/pose_covariance.h"

#include <cmath>

#include "estimator/pose_manifold.h"

namespace vigil::estimator {
namespace {

// The square root of the gauge information in the pose tangent: position, and the world yaw
// delta yaw = e_z^T R_WB delta theta_B.
Eigen::Matrix<double, 4, 6> GaugeRows(const Eigen::Quaterniond& q_WB) {
  const double root = std::sqrt(kGaugeInformation);
  Eigen::Matrix<double, 4, 6> J = Eigen::Matrix<double, 4, 6>::Zero();
  J.topLeftCorner<3, 3>() = root * Eigen::Matrix3d::Identity();
  J.block<1, 3>(3, 3) = root * Eigen::Vector3d::UnitZ().transpose() * q_WB.toRotationMatrix();
  return J;
}

}  // namespace

LinearPrior GaugePrior(double* pose) {
  LinearPrior prior;
  prior.blocks.push_back({pose, kPoseSize, kPoseTangentSize, std::vector<double>(pose, pose + kPoseSize)});
  prior.J = GaugeRows(PoseQ(pose).normalized());
  prior.r = Eigen::VectorXd::Zero(4);
  prior.H = prior.J.transpose() * prior.J;
  prior.g = Eigen::VectorXd::Zero(kPoseTangentSize);
  return prior;
}

void AddGaugeInformation(const Eigen::Quaterniond& q_WB, int column, Eigen::MatrixXd* H) {
  const Eigen::Matrix<double, 4, 6> J = GaugeRows(q_WB);
  H->block<6, 6>(column, column) += J.transpose() * J;
}

}  // namespace vigil::estimator
