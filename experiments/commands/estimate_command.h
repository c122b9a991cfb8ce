// `vigil estimate`: vigil's estimator alone on a recording (a EuRoC folder, or a vigil dataset), writing its
// trajectory. It is also the first external estimator: run as `estimator.external.command` on the recording
// a run writes (experiments/runs/external_recording.h), it reproduces the built-in estimate of that run.
//
// The estimator's input is what `vigil run --dataset` gives it (MakeEstimatorInput): the recording's IMU,
// feature tracks (features.csv beside mav0/; tracked from the cam0 images by the front-end when there is
// none), camera and ground truth, with the configuration's estimator options, gravity and seed. The IMU noise
// densities are those of imu0/sensor.yaml when the recording has one, else the configuration's imu.noise.
// A detections.csv beside mav0/ (what a run's detector flagged) feeds estimator.mitigation.inflate.
// The estimator backend keys (estimator.backend, estimator.external) are ignored: it is vigil's estimator.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vigil::experiments {

// Writes into `dir` (staged; refused over the inputs, and when not empty unless `force`):
//   stamped_traj_estimate.txt   TUM, seconds, one row per frame after initialization
//   status.json                 {"status": "ok"|"failed", "failure_reason", "frames", "keyframes", "resets",
//                                "initialized_at_s", "output_poses", "tracked", "wall_time_s"}
// Returns status.json. InputError for bad input (nothing written).
nlohmann::json EstimateToDirectory(const std::filesystem::path& dataset, const std::string& config_path,
                                   const std::vector<std::string>& overrides,
                                   const std::filesystem::path& dir, bool force);

}  // namespace vigil::experiments
