// One run: simulate (or read a dataset), detect + mitigate, estimate, evaluate; write a run directory.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/dataset.h"
#include "detectors/template_library.h"
#include "estimator/estimator_input.h"
#include "experiments/runs/run_config.h"

namespace vigil::experiments {

struct RunOptions {
  std::filesystem::path
      dataset_dir;  // read this dataset instead of simulating (empty: simulate from the config)
  bool write_trajectories = true;  // stamped_groundtruth.txt / stamped_traj_estimate.txt / detections.csv
  bool write_figure_data = true;   // landmarks.csv / imu_axis.csv (what the run's figures draw)
  // DTW template library to use (a sweep builds one per setting and shares it). Null:
  // detector.dtw.templates_file, else a library built from a glitch-free simulation with seed
  // DeriveSeed(config.seed, "templates").
  const detectors::TemplateLibrary* templates = nullptr;
};

// Runs `config` and writes config.yaml, metrics.json and (optionally) the trajectories and figure data into
// `dir`, which must exist (the caller stages and renames it). Returns the metrics.json document. Estimator
// divergence or an exception inside the estimator gives status "failed" with its reason, not an exception;
// bad input throws InputError.
nlohmann::json ExecuteRun(const RunConfig& config, const RunOptions& options,
                          const std::filesystem::path& dir);

// vigil's own estimator on `dataset` with `imu` as its IMU: the run's estimator stage, and `vigil estimate`.
// An exception inside the estimator gives ok = false with its reason; InputError passes through.
estimator::EstimatorResult Estimate(const RunConfig& config, const Dataset& dataset, ImuStream imu,
                                    std::vector<uint8_t> flagged);

}  // namespace vigil::experiments
