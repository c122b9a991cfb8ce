// `vigil track` without the process: the visual front-end alone on a dataset's camera images, written as
// feature tracks with the tracker's statistics and, for a rendered dataset, their errors against the scene.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vigil::experiments {

struct TrackRequest {
  std::string dataset;                 // a dataset directory with mav0/cam0 (EuRoC layout)
  std::string output;                  // the directory to write
  std::vector<std::string> overrides;  // frontend.key.path=value, applied in order to the defaults
  bool force = false;                  // replace an output directory vigil wrote
};

struct TrackResult {
  nlohmann::json frontend;  // frontend.json
  bool has_groundtruth = false;
  std::optional<double> outlier_ratio;  // of the reprojection errors, when the tracks were evaluated
  double outlier_threshold_px = 0.0;
};

// Checks the overrides and reads and tracks everything first (InputError, nothing written: a bad key or
// value, no camera images). Then writes into `output` (staged, refused over the dataset, and when not empty
// unless `force`):
//   features.csv    the published frames' feature tracks
//   frontend.json   the tracker's statistics (experiments/runs/frontend_metrics.h), the dataset, the time per
//                   image, and the reprojection errors when the dataset has ground truth and a scene.obj
//   config.yaml     the front-end options applied (under "frontend:", as in a run config)
TrackResult TrackToDirectory(const TrackRequest& request);

// The line `vigil track` reports (without "vigil track: " and the newline).
std::string TrackSummary(const TrackRequest& request, const TrackResult& result);

}  // namespace vigil::experiments
