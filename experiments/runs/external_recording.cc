#include "experiments/runs/external_recording.h"

#include <stdexcept>
#include "core/config.h"

#include "core/error.h"
#include "core/output.h"
#include "detectors/detector.h"

namespace vigil::experiments {
namespace fs = std::filesystem;

void WriteExternalRecording(const fs::path& dir, const RunConfig& config, const Dataset& dataset,
                            const ImuStream& imu, const std::vector<uint8_t>& flagged,
                            const std::vector<CameraImage>& images,
                            const EurocImuSensor* dataset_imu_sensor) {
  Dataset seen;
  seen.imu = imu;
  seen.camera = dataset.camera;
  seen.groundtruth = dataset.groundtruth;
  EurocImuSensor sensor;
  if (dataset_imu_sensor) {
    sensor = *dataset_imu_sensor;
    sensor.T_BS = Eigen::Isometry3d::Identity();  // the IMU is the body frame in what vigil writes
  } else {
    sensor.rate_hz = config.sim.imu.rate_hz;
    const sim::ImuNoiseOptions& noise = config.sim.imu.noise;
    sensor.gyroscope_noise_density = noise.gyro_noise_density;
    sensor.gyroscope_random_walk = noise.gyro_bias_random_walk;
    sensor.accelerometer_noise_density = noise.accel_noise_density;
    sensor.accelerometer_random_walk = noise.accel_bias_random_walk;
  }

  std::vector<int64_t> frame_times;
  if (!images.empty()) {
    for (const CameraImage& image : images) frame_times.push_back(image.t_ns);
  } else {
    for (const CameraFrame& frame : dataset.frames) frame_times.push_back(frame.t_ns);
  }
  WriteEuroc(dir, seen, sensor, frame_times);
  const fs::path image_dir = EurocImageDir(dir);
  for (const CameraImage& image : images) {
    std::error_code ec;
    fs::create_symlink(fs::absolute(image.path), image_dir / EurocImageName(image.t_ns), ec);
    if (ec)
      throw std::runtime_error((image_dir / EurocImageName(image.t_ns)).string() + ": cannot link " +
                               image.path + ": " + ec.message());
  }
  WriteFileAtomic(dir / dataset_files::kFeatures, FeaturesCsv(dataset.frames));
  if (!flagged.empty() && flagged.size() == imu.size() &&
      config.detector.type != detectors::DetectorType::kNone)
    WriteFileAtomic(dir / kRecordingDetections, detectors::DetectionsCsv(imu, flagged));
  RunConfig resolved = config;  // ToYaml visits (non-const)
  WriteFileAtomic(dir / dataset_files::kConfig, config::ToYaml(resolved));
}

}  // namespace vigil::experiments
