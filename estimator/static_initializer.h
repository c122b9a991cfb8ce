// A static start (estimator.zero_velocity.static_init): when the whole initialization window stands still,
// the window is initialized from its IMU alone, as OpenVINS's static initializer does; otherwise the wrapped
// initializer runs.
//
// Standing still, the accelerometer measures gravity plus its bias and the gyro measures its bias: the mean
// specific force gives the direction of up in the body frame (the roll and pitch; the accelerometer bias
// cannot be told apart from a tilt and stays zero) and the mean rotation rate the gyro bias. Every window
// frame gets that orientation with zero yaw, zero position and zero velocity. Nothing can be triangulated
// without motion, so no landmarks; the estimator holds the state with zero-velocity factors until an
// interval moves (InitResult::stationary).
#pragma once

#include <memory>

#include "estimator/initializer.h"
#include "estimator/zero_velocity_options.h"

namespace vigil::estimator {

class StaticInitializer : public Initializer {
 public:
  StaticInitializer(std::unique_ptr<Initializer> moving, const ZeroVelocityOptions& options, double fx);

  bool TryInitialize(const std::vector<InitFrame>& window, InitResult* result) override;
  bool CanReinitialize() const override { return moving_->CanReinitialize(); }

 private:
  std::unique_ptr<Initializer> moving_;
  ZeroVelocityOptions options_;
  double fx_;
};

// The static initialization of a window assumed still (every frame gets the same state); false when the
// window has no IMU or the mean specific force is zero.
bool InitializeStill(const std::vector<InitFrame>& window, InitResult* result);

}  // namespace vigil::estimator
