// What a run hands to the estimator and to the evaluation, derived from its dataset and configuration.
#pragma once

#include "core/dataset.h"
#include "core/types.h"
#include "estimator/estimator_input.h"
#include "experiments/runs/run_config.h"

namespace vigil::experiments {

// The estimator's input: `imu` (the cleaned or raw stream), the dataset's feature tracks and camera, the IMU
// noise densities of the config's imu.noise section (used as the estimator's noise model even when the
// simulator's noise is disabled: an optimization needs finite weights), gravity, ground truth (read only by
// `estimator.init: groundtruth`), the run seed and the detector's flags per sample of `imu` (`flagged`, may
// be empty; read by estimator.mitigation.inflate).
estimator::EstimatorInput MakeEstimatorInput(const RunConfig& config, const Dataset& dataset, ImuStream imu,
                                             std::vector<uint8_t> flagged = {});

// The ground-truth body pose at every camera frame time (interpolated from the IMU-rate ground truth: linear
// in position, slerp in orientation); frames outside the ground truth's time span are left out.
Trajectory GroundTruthAtFrames(const std::vector<NavState>& groundtruth,
                               const std::vector<CameraFrame>& frames);

}  // namespace vigil::experiments
