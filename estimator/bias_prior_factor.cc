#include "estimator/bias_prior_factor.h"

namespace vigil::estimator {
namespace {

double Weight(double std) { return std > 0.0 ? 1.0 / std : 0.0; }

}  // namespace

BiasPriorFactor::BiasPriorFactor(const Eigen::Vector3d& b_a0, const Eigen::Vector3d& b_g0,
                                 double accel_bias_std, double gyro_bias_std)
    : b_a0_(b_a0), b_g0_(b_g0), accel_weight_(Weight(accel_bias_std)), gyro_weight_(Weight(gyro_bias_std)) {}

bool BiasPriorFactor::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const Eigen::Map<const Eigen::Vector3d> b_a(parameters[0] + 3), b_g(parameters[0] + 6);
  Eigen::Map<Eigen::Matrix<double, 6, 1>> r(residuals);
  r.head<3>() = accel_weight_ * (b_a - b_a0_);
  r.tail<3>() = gyro_weight_ * (b_g - b_g0_);
  if (jacobians != nullptr && jacobians[0] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, 6, kSpeedBiasSize, Eigen::RowMajor>> jac(jacobians[0]);
    jac.setZero();
    jac.block<3, 3>(0, 3).diagonal().setConstant(accel_weight_);
    jac.block<3, 3>(3, 6).diagonal().setConstant(gyro_weight_);
  }
  return true;
}

}  // namespace vigil::estimator
