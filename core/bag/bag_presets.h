// The topic names and sensor calibrations of the public datasets whose ROS 1 bags `vigil import` knows:
//   euroc  EuRoC MAV (ETH Zurich ASL): /imu0 (ADIS16448), /cam0/image_raw (MT9M034, 752 x 480, mono8),
//          ground truth /vicon/firefly_sbx/firefly_sbx (Vicon Room sequences; the Machine Hall bags have only
//          the Leica's position, /leica/position, which is not a pose). Its published imu0 noise model and
//          cam0 calibration (pinhole, radial-tangential; the same for every sequence).
//   tumvi  TUM-VI (TU Munich): /imu0 (BMI160), /cam0/image_raw (512 x 512 or 1024 x 1024, mono16), ground
//          truth /vrpn_client/raw_transform (the motion-capture marker's pose). Its published IMU noise
//          model; no camera: TUM-VI's cameras are fisheye lenses calibrated with the equidistant model, which
//          vigil's pinhole camera cannot describe.
// The numbers are the datasets' published calibrations (docs/datasets.md says where they come from).
#pragma once

#include <optional>
#include <string>

#include "core/camera.h"
#include "core/euroc.h"

namespace vigil::bag {

struct BagPreset {
  const char* name;
  const char* imu_topic;
  const char* image_topic;
  const char* groundtruth_topic;
  const char* imu_comment;  // the `comment` of the imu0/sensor.yaml written
  EurocImuSensor imu;
  std::optional<CameraModel> camera;  // cam0, with T_BC in the IMU's frame; none: see `no_camera_reason`
  const char* camera_comment;
  const char* no_camera_reason;
};

// "euroc, tumvi".
std::string BagPresetNames();
// The preset of that name; InputError "--preset: 'NAME' is not a preset (euroc, tumvi)".
const BagPreset& FindBagPreset(const std::string& name);

}  // namespace vigil::bag
