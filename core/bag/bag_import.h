// `vigil import` without the process: a ROS 1 bag into the EuRoC layout vigil reads (core/euroc.h).
//
//   sensor_msgs/Imu        -> mav0/imu0/data.csv (header stamps; angular velocity, linear acceleration)
//   sensor_msgs/Image      -> mav0/cam0/data/<stamp>.png (8-bit grayscale, core/bag/gray_image.h), data.csv
//   a ground-truth topic   -> mav0/state_groundtruth_estimate0/data.csv (geometry_msgs/PoseStamped,
//                             TransformStamped or nav_msgs/Odometry)
//   the sensors' calibration -> mav0/imu0/sensor.yaml, mav0/cam0/sensor.yaml (given files, or the preset's)
//   what was imported      -> import.yaml beside mav0/
//
// Times are the messages' header stamps. Images and ground-truth poses outside the IMU's time span are left
// out (counted in the result): vigil ties every frame and pose to IMU samples on both sides. The ground
// truth's velocity is the Odometry's (rotated into the world frame), or else the central difference of the
// positions; its biases are unknown and written as 0.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace vigil::bag {

// The value of a topic option that leaves that stream out (--image-topic none, --groundtruth-topic none).
inline constexpr const char* kNoTopic = "none";

struct BagImportRequest {
  std::string bag;                // the ROS 1 bag
  std::string output;             // the directory to write
  std::string preset = "euroc";   // default topics and calibrations (core/bag/bag_presets.h)
  std::string imu_topic;          // empty: the preset's
  std::string image_topic;        // empty: the preset's; "none": no images
  std::string groundtruth_topic;  // empty: the preset's when the bag has it; "none": no ground truth
  std::string imu_yaml;           // an imu0 sensor.yaml to copy; empty: the preset's noise model
  std::string camera_yaml;        // a cam0 sensor.yaml to copy; empty: the preset's calibration
  bool force = false;             // replace an output directory vigil wrote
};

struct BagImportResult {
  std::size_t imu_samples = 0;
  std::size_t images = 0, images_outside = 0;  // written; left out (outside the IMU's time span)
  std::size_t poses = 0, poses_outside = 0;
  std::string image_topic, groundtruth_topic;  // as imported; empty: none
  std::string encodings;                       // the image encodings met, e.g. "mono8"
  std::string groundtruth_note;                // why there is no ground truth, when the preset's is absent
};

// Called after each message with the number read and the total of the imported topics.
using ImportProgress = std::function<void(std::size_t done, std::size_t total)>;

// Checks the options, the sensor files, the bag and its topics first (InputError, nothing written: an
// unknown preset, a missing topic or one of another type, a camera without calibration, an output over an
// input). Then converts every message into a staged directory that is renamed into place only when complete
// and read back by vigil's own reader (ReadRecording). Bad input stops it with InputError, nothing written:
// a corrupt or truncated bag ("BAG: corrupt ROS bag: ..."), a message that does not decode, an unsupported
// image encoding, an image of another size than the camera's, a stamp that goes back
// ("BAG: TOPIC: message N: ...", N counted from 1 in the bag's time order).
BagImportResult ImportBag(const BagImportRequest& request, const ImportProgress& progress = {});

// The line `vigil import` reports (without "vigil import: " and the newline).
std::string BagImportSummary(const BagImportRequest& request, const BagImportResult& result);

}  // namespace vigil::bag
