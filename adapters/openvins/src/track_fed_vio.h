// OpenVINS's VioManager fed with feature tracks instead of images: each camera frame's tracks go into
// OpenVINS's simulated-measurement tracker (TrackSIM), and until the filter is initialized, OpenVINS's own
// inertial initializer is tried on them, as VioManager does for tracked images (VioManager's public
// feed_measurement_simulation needs an initialized filter, so the initializer is reached from a subclass).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <utility>
#include <vector>

#include "core/VioManager.h"

namespace ov_core {
class TrackSIM;
}

namespace vigil_openvins {

class TrackFedVio : public ov_msckf::VioManager {
 public:
  explicit TrackFedVio(ov_msckf::VioManagerOptions& options);

  // One camera frame at time t [s] with (id, undistorted pixel) tracks of camera 0. IMU samples up to at
  // least t must have been fed (feed_measurement_imu).
  void FeedTracks(double t_s, const std::vector<std::pair<size_t, Eigen::VectorXf>>& uv);

  // The filter's IMU pose (body = IMU) in OpenVINS's world frame, and the time of its state [s].
  double state_time_s() const;
  Eigen::Vector3d p_WB() const;
  Eigen::Quaterniond q_WB() const;

 private:
  std::shared_ptr<ov_core::TrackSIM> tracks_;
};

}  // namespace vigil_openvins
