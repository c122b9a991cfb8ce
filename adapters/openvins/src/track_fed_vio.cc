#include "track_fed_vio.h"

#include <opencv2/core.hpp>

#include "init/InertialInitializer.h"
#include "state/State.h"
#include "track/TrackSIM.h"
#include "types/IMU.h"

namespace vigil_openvins {

TrackFedVio::TrackFedVio(ov_msckf::VioManagerOptions& options) : ov_msckf::VioManager(options) {
  // The tracker becomes a feed of given tracks; the initializer must read that tracker's feature database.
  tracks_ =
      std::make_shared<ov_core::TrackSIM>(state->_cam_intrinsics_cameras, state->_options.max_aruco_features);
  trackFEATS = tracks_;
  initializer =
      std::make_shared<ov_init::InertialInitializer>(params.init_options, trackFEATS->get_feature_database());
}

void TrackFedVio::FeedTracks(double t_s, const std::vector<std::pair<size_t, Eigen::VectorXf>>& uv) {
  tracks_->feed_measurement_simulation(t_s, {0}, {uv});
  // The update reads the frame's time and camera; the images themselves are never looked at.
  ov_core::CameraData frame;
  frame.timestamp = t_s;
  frame.sensor_ids.push_back(0);
  const auto& camera = state->_cam_intrinsics_cameras.at(0);
  frame.images.push_back(cv::Mat::zeros(cv::Size(camera->w(), camera->h()), CV_8UC1));
  frame.masks.push_back(cv::Mat::zeros(cv::Size(camera->w(), camera->h()), CV_8UC1));
  if (!is_initialized_vio) {
    is_initialized_vio = try_to_initialize(frame);  // runs in this thread (multi_threading_subs: false)
    if (!is_initialized_vio) return;
  }
  do_feature_propagate_update(frame);
}

double TrackFedVio::state_time_s() const { return state->_timestamp; }

Eigen::Vector3d TrackFedVio::p_WB() const { return state->_imu->pos(); }

// OpenVINS keeps R_GtoI (world -> IMU); the body's orientation in the world is its transpose.
Eigen::Quaterniond TrackFedVio::q_WB() const {
  return Eigen::Quaterniond(Eigen::Matrix3d(state->_imu->Rot().transpose())).normalized();
}

}  // namespace vigil_openvins
