// The recording an external estimator sees, written in the EuRoC ASL layout (core/euroc.h):
//
//   DIR/mav0/imu0/data.csv, sensor.yaml      the IMU after faults, detection and mitigation; the rate, noise
//                                            densities and random walks of the dataset's own
//                                            imu0/sensor.yaml when the run reads a dataset that has one,
//                                            else those the run configures (imu.rate_hz, imu.noise)
//   DIR/mav0/cam0/data.csv, sensor.yaml      one row per camera frame; the camera model
//   DIR/mav0/cam0/data/<t_ns>.png            symbolic links to the recording's images, when it has them
//                                            (a simulated run without rendered images lists the frames only)
//   DIR/mav0/state_groundtruth_estimate0/    the ground truth, when known
//   DIR/features.csv                         vigil's feature tracks (formats.md)
//   DIR/detections.csv                       the detector's flag per IMU sample, when a detector ran
//                                            (`#timestamp [ns],flagged`; read by in-estimator mitigation)
//   DIR/config.yaml                          the run's resolved configuration
//
// `vigil estimate DIR` reads it back and gives vigil's estimator the same input as inside `vigil run`.
#pragma once

#include <filesystem>
#include <vector>

#include "core/dataset.h"
#include "core/euroc.h"
#include "experiments/runs/run_config.h"

namespace vigil::experiments {

// Writes the recording into `dir` (which must exist): `dataset`'s camera, frames and ground truth with `imu`
// as the IMU and `flagged` (one per sample of `imu`, else none) as its detections, linking `images` (empty:
// none). imu0/sensor.yaml is `dataset_imu_sensor` (the dataset's own) when given, else the configuration's.
void WriteExternalRecording(const std::filesystem::path& dir, const RunConfig& config, const Dataset& dataset,
                            const ImuStream& imu, const std::vector<uint8_t>& flagged,
                            const std::vector<CameraImage>& images,
                            const EurocImuSensor* dataset_imu_sensor = nullptr);

// The detections.csv of a recording, beside its mav0/.
inline constexpr const char* kRecordingDetections = "detections.csv";

}  // namespace vigil::experiments
