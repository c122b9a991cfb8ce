#include "estimator/static_initializer.h"

#include <utility>

#include <Eigen/Geometry>

#include "core/so3.h"
#include "estimator/zero_velocity_detector.h"

namespace vigil::estimator {

StaticInitializer::StaticInitializer(std::unique_ptr<Initializer> moving, const ZeroVelocityOptions& options,
                                     double fx)
    : moving_(std::move(moving)), options_(options), fx_(fx) {}

bool StaticInitializer::TryInitialize(const std::vector<InitFrame>& window, InitResult* result) {
  bool still = window.size() >= 2;
  for (std::size_t k = 1; still && k < window.size(); ++k)
    still = window[k].imu_from_prev && IntervalIsStationary(window[k - 1].features_n, window[k].features_n,
                                                            *window[k].imu_from_prev, fx_, options_);
  if (still && InitializeStill(window, result)) return true;
  return moving_->TryInitialize(window, result);
}

bool InitializeStill(const std::vector<InitFrame>& window, InitResult* result) {
  *result = InitResult{};
  Eigen::Vector3d sum_a_B = Eigen::Vector3d::Zero(), sum_w_B = Eigen::Vector3d::Zero();
  int samples = 0;
  for (std::size_t k = 1; k < window.size(); ++k) {
    if (!window[k].imu_from_prev) continue;
    for (const Preintegration::Step& s : window[k].imu_from_prev->steps()) {
      sum_a_B += s.a_B;
      sum_w_B += s.w_B;
      ++samples;
    }
  }
  if (samples == 0 || sum_a_B.norm() == 0.0) {
    result->failure_reason = "static initialization: no IMU samples";
    return false;
  }
  // Still: a_B = R_WB^T (0, 0, g) + b_a, so R_WB turns the mean specific force to +z; yaw zero.
  Eigen::Matrix3d R_WB =
      Eigen::Quaterniond::FromTwoVectors(sum_a_B, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  R_WB = RotZ(-YawOf(R_WB)) * R_WB;
  NavState still;
  still.q_WB = Eigen::Quaterniond(R_WB).normalized();
  still.b_g = sum_w_B / samples;
  for (const InitFrame& f : window) {
    still.t_ns = f.t_ns;
    result->states.push_back(still);
  }
  result->stationary = true;
  return true;
}

}  // namespace vigil::estimator
