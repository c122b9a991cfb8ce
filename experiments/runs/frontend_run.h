// The visual front-end inside `vigil run`: when the run's feature tracks come from the tracker instead of a
// features.csv, and the "frontend" object of its metrics.json.
//
// - A simulated run with frontend.features: tracked renders the scenario's camera images in memory (the same
//   images `vigil simulate --images` writes: sim/image_renderer.h), tracks them and evaluates the tracks
//   against the rendered scene (sim/scene.h) and the ground truth.
// - A run on a recording tracks its cam0 images when frontend.features is tracked or when the recording has
//   images but no features.csv (a EuRoC folder as published); the tracks are evaluated when the recording
//   has ground truth and a scene.obj beside its mav0/ (a rendered dataset).
// The estimator then sees the tracked frames only; it does not know where they came from.
#pragma once

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/dataset.h"
#include "core/euroc.h"
#include "core/mesh.h"
#include "experiments/runs/run_config.h"

namespace vigil::experiments {

struct FrontendRunResult {
  nlohmann::json metrics;  // the "frontend" object (experiments/runs/frontend_metrics.h)
  double track_s = 0.0;    // wall time of rendering (simulated runs) and tracking
};

// Renders and tracks the images of `dataset` = sim::Simulate(config.sim, config.seed); replaces its frames.
FrontendRunResult TrackSimulation(const RunConfig& config, Dataset* dataset);

// Tracks `recording`'s images (InputError when it has none); replaces recording->dataset.frames. `dir` is the
// dataset directory the recording was read from (where scene.obj may sit).
FrontendRunResult TrackRecording(const RunConfig& config, const std::filesystem::path& dir,
                                 Recording* recording);

// scene.obj of a dataset directory: in `dir`, or beside its mav0/ when `dir` is mav0 itself.
std::optional<TriangleMesh> FindSceneMesh(const std::filesystem::path& dir);

}  // namespace vigil::experiments
