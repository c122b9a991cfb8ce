// The simulator: a whole dataset (docs/formats.md) from SimOptions and a seed.
//
// Simulate() chains the stages: motion model -> IMU + ground truth (imu_synthesizer) -> glitches
// (glitch_injector) and the other IMU faults (imu_faults.h gives their order) -> landmarks -> feature tracks
// (camera_simulator). With imu.source recording, the recorded IMU and ground truth replace the first two
// (a semi-real dataset, sim/semi_real.h). Each random stream derives from (seed, purpose): "imu_noise",
// "imu_bias", "glitch", "glitch_offset", "imu_drop", "imu_duplicate", "imu_jitter", "landmarks", "pixels"; so
// the same options and seed give the same dataset bit for bit, and e.g. glitch or fault settings never change
// the IMU noise.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/dataset.h"
#include "core/euroc.h"
#include "sim/imu_synthesizer.h"
#include "sim/scene.h"
#include "sim/sim_options.h"
#include "sim/trajectory_model.h"

namespace vigil::sim {

// Simulates one recording. Throws InputError for bad options (naming the key).
Dataset Simulate(const SimOptions& options, uint64_t seed);

// Only the first stage of Simulate(): the clean IMU stream (the sensor's constant errors, quantization and
// timing faults included; no glitches or clipping) and ground truth (no landmarks or camera), bit-identical
// to Simulate(options, seed).imu_clean / .groundtruth. For callers that need only normal motion (DTW
// templates). Throws InputError for bad options.
ImuSynthesis SimulateImu(const SimOptions& options, uint64_t seed);

// imu0/sensor.yaml of the simulated IMU: its rate and noise model (zeros when the noise is disabled).
EurocImuSensor ImuSensorOf(const ImuOptions& imu);

// The rendered world of the scenario (sim/scene.h): the scene its landmark layout stands for, around the path
// of `motion` (the scenario's trajectory) over duration_s.
Scene ScenarioScene(const SimOptions& options, const TrajectoryModel& motion);

// The image side of a dataset directory `dir` (existing) for `dataset` = Simulate(options, seed): the EuRoC
// layout mav0/ (core/euroc.h) with one rendered PNG per camera frame of dataset.frames, and scene.obj
// (core/mesh.h). Returns the PNG bytes written.
std::uintmax_t WriteImages(const SimOptions& options, uint64_t seed, const Dataset& dataset,
                           const std::filesystem::path& dir);

// `vigil simulate`: simulates and writes the dataset directory `dir` (staged in a temporary sibling and
// renamed at the end; a non-empty `dir` is refused unless `force`). `config_yaml` is written as config.yaml:
// the fully resolved configuration that reproduces the dataset. With images.enabled, also WriteImages().
Dataset SimulateToDirectory(const SimOptions& options, uint64_t seed, const std::string& config_yaml,
                            const std::filesystem::path& dir, bool force);

}  // namespace vigil::sim
