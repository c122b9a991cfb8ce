// The EuRoC ASL dataset layout ("mav0/"), written and read as the published EuRoC sequences are laid out:
//
//   mav0/imu0/data.csv                         #timestamp [ns],w_RS_S_x [rad s^-1],...,a_RS_S_z [m s^-2]
//   mav0/imu0/sensor.yaml                      T_BS, rate_hz, gyroscope/accelerometer noise densities and
//                                              random walks
//   mav0/cam0/data.csv                         #timestamp [ns],filename
//   mav0/cam0/data/<timestamp>.png             8-bit grayscale images
//   mav0/cam0/sensor.yaml                      T_BS {cols: 4, rows: 4, data: [16]}, rate_hz, resolution [w,
//   h],
//                                              camera_model: pinhole, intrinsics [fu, fv, cu, cv],
//                                              distortion_model: radial-tangential,
//                                              distortion_coefficients [k1, k2, p1, p2]
//   mav0/state_groundtruth_estimate0/data.csv  vigil's groundtruth.csv layout (optional)
//
// sensor.yaml files begin with OpenCV's "%YAML:1.0" directive, which is read (and written) as published.
// T_BS is the sensor's pose in the body frame (sensor -> body). vigil's body frame is the IMU's: the camera's
// T_BC is T_BS(imu0)^-1 T_BS(cam0) (T_BS(imu0) is the identity in EuRoC and in what vigil writes).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/dataset.h"
#include "core/output.h"

namespace vigil {

namespace euroc_files {
inline constexpr const char* kMav0 = "mav0";
inline constexpr const char* kImu = "imu0";
inline constexpr const char* kCamera = "cam0";
inline constexpr const char* kGroundTruth = "state_groundtruth_estimate0";
inline constexpr const char* kData = "data.csv";
inline constexpr const char* kSensor = "sensor.yaml";
inline constexpr const char* kImages = "data";  // the image folder inside cam0/
}  // namespace euroc_files

// imu0/sensor.yaml.
struct EurocImuSensor {
  double rate_hz = 200.0;
  double gyroscope_noise_density = 0.0;      // [rad / s / sqrt(Hz)]
  double gyroscope_random_walk = 0.0;        // [rad / s^2 / sqrt(Hz)]
  double accelerometer_noise_density = 0.0;  // [m / s^2 / sqrt(Hz)]
  double accelerometer_random_walk = 0.0;    // [m / s^3 / sqrt(Hz)]
  Eigen::Isometry3d T_BS = Eigen::Isometry3d::Identity();
};

// One row of cam0/data.csv: the image's timestamp, its absolute path, and where the row was read (errors
// about the image name it: "data.csv:LINE: path: reason").
struct CameraImage {
  int64_t t_ns = 0;
  std::string path;
  std::string list_path;  // cam0/data.csv
  int list_line = 0;
};

// sensor.yaml text (with the %YAML:1.0 line and EuRoC's comments); `comment` names the sensor.
std::string EurocImuSensorYaml(const EurocImuSensor& sensor,
                               const std::string& comment = "vigil simulated IMU");
// From the camera model: T_BS = T_BC, resolution, intrinsics, distortion (imu0's T_BS taken as identity).
std::string EurocCameraSensorYaml(const CameraModel& camera,
                                  const std::string& comment = "vigil rendered camera");
// cam0/data.csv of images named <timestamp>.png.
std::string EurocImageListCsv(const std::vector<int64_t>& times_ns);
// The image file name of a timestamp: "<t_ns>.png".
std::string EurocImageName(int64_t t_ns);

// The physical bounds a sensor.yaml must respect (docs/safety.md): a value beyond them is a typo or a corrupt
// file, refused rather than run on.
inline constexpr double kMinSensorRateHz = 0.1, kMaxSensorRateHz = 100000.0;  // rate_hz
inline constexpr double kMaxSensorOffsetM = 100.0;                            // |T_BS translation|
inline constexpr double kMaxFocalLengthPx = 100000.0;                         // fu, fv (from 1 px)
inline constexpr double kMaxDistortionCoefficient = 10.0;                     // |k1|, |k2|, |p1|, |p2|

// Readers; errors are "file:line: key: reason". The camera reader needs T_BS, rate_hz, resolution,
// intrinsics (pinhole; the principal point inside the image), and reads distortion_coefficients
// (radial-tangential, or none/absent = zeros).
EurocImuSensor ReadEurocImuSensorYaml(const TextFile& file);
CameraModel ReadEurocCameraSensorYaml(const TextFile& file);
// cam0/data.csv: rows "timestamp,filename" with increasing timestamps and a file name (relative to
// `image_dir`); with `check_files`, each image must exist as a regular file (its content and size are
// checked when it is loaded: CheckImageSize).
std::vector<CameraImage> ReadEurocImageList(const TextFile& file, const std::filesystem::path& image_dir,
                                            bool check_files = true);

// InputError "data.csv:LINE: PATH: image is W x H, cam0/sensor.yaml declares W' x H'" unless the loaded
// image has the camera's resolution.
void CheckImageSize(const CameraImage& image, int width, int height, const CameraModel& camera);

// The mav0/ directory of `dir`: `dir` itself when it is named mav0 or holds imu0/, else dir/mav0 when that
// exists; an empty path otherwise.
std::filesystem::path FindMav0(const std::filesystem::path& dir);

// A recording read from a dataset directory in any accepted layout (ReadRecording).
struct Recording {
  Dataset dataset;                  // imu, camera, groundtruth (empty when unknown), frames, landmarks
  std::vector<CameraImage> images;  // cam0 images (empty without a camera)
  EurocImuSensor imu_sensor;        // from imu0/sensor.yaml (EuRoC layouts)
  bool has_camera = false;          // a camera model is known (camera.yaml or cam0/)
  bool has_features = false;        // features.csv was read into dataset.frames
  bool has_groundtruth = false;
  std::string layout;  // "vigil" (imu.csv, ...) or "euroc" (mav0/ only)
};

// Reads a recording:
// - a vigil dataset directory (imu.csv beside groundtruth.csv, ...; ReadDataset), with its mav0/ images when
//   vigil simulate --images wrote them;
// - a EuRoC folder as published: the folder holding mav0/, or mav0/ itself. IMU from imu0/, camera from cam0/
//   (optional), ground truth from state_groundtruth_estimate0/ (optional), feature tracks from a features.csv
//   beside mav0/ (optional; `vigil track` writes one), at the image timestamps; imu_clean.csv and
//   glitches.csv beside mav0/ (optional; `vigil inject` writes them).
// Both layouts: the ground truth must lie inside the IMU's time span and so must every camera image's time
// (core/dataset.h CheckGroundTruthInImuSpan, CheckCameraTimeInImuSpan).
// Errors name the file and line; a folder that is neither layout is "DIR: not a dataset directory (...)".
// With `check_image_files` false, cam0/data.csv may list images that are absent (a recording of feature
// tracks only, whose frame times the list gives); whoever loads an image then finds it missing.
Recording ReadRecording(const std::filesystem::path& dir, bool check_image_files = true);

// Writes mav0/ into `dir` (which must exist): imu0 (data.csv, sensor.yaml), cam0 (data.csv listing
// `image_times_ns`, sensor.yaml; the images themselves are written by the caller into ImageDir(dir)) and the
// ground truth when `dataset.groundtruth` is not empty.
void WriteEuroc(const std::filesystem::path& dir, const Dataset& dataset, const EurocImuSensor& imu_sensor,
                const std::vector<int64_t>& image_times_ns);
// dir/mav0/cam0/data.
std::filesystem::path EurocImageDir(const std::filesystem::path& dir);

}  // namespace vigil
