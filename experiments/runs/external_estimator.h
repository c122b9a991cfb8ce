// The estimator stage of a run with `estimator.backend: external`: write the recording the program sees,
// run it, read its trajectory.
//
// Everything the program does wrong is a failed run with its reason, never an exception: a non-zero exit or
// a signal, the timeout (its process group is killed), no trajectory, an empty one, non-finite or unsorted
// rows, timestamps outside the recording. In the run directory:
//   external/stdout.txt, external/stderr.txt   what the program printed
//   external/output/                           its {output} folder (the trajectory among what it wrote)
//   external/recording/                        the recording, with estimator.external.keep_recording
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/dataset.h"
#include "core/euroc.h"
#include "estimator/estimator_input.h"
#include "experiments/runs/run_config.h"

namespace vigil::experiments {

struct ExternalEstimate {
  // ok, failure_reason, trajectory, frames (= trajectory rows), initialized_at_s (first row).
  estimator::EstimatorResult result;
  // metrics.json's "external" object: command (as run), outcome, exit_code, rows, and wall_time_s
  // {write_recording, process, read} (the overhead of the external path next to the process itself).
  nlohmann::json json;
};

// Runs config.estimator.external on `dataset` with `imu` (after detection and mitigation) as its IMU and
// `flagged` its detector's flags (may be empty), `images` (may be empty) as its camera images; `run_dir`
// receives the files listed above. `dataset_imu_sensor`: the read dataset's own imu0/sensor.yaml, which the
// recording then carries (null: the configuration's rate and imu.noise).
ExternalEstimate RunExternalEstimator(const RunConfig& config, const Dataset& dataset, const ImuStream& imu,
                                      const std::vector<uint8_t>& flagged,
                                      const std::vector<CameraImage>& images,
                                      const std::filesystem::path& run_dir,
                                      const EurocImuSensor* dataset_imu_sensor = nullptr);

// "estimator.external.input: reason" when `config` runs an external estimator that needs what its recording
// lacks: camera images (`has_images`) or feature tracks (`has_features`); empty otherwise.
std::string ExternalInputProblem(const RunConfig& config, bool has_images, bool has_features);

}  // namespace vigil::experiments
