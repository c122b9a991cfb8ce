// The "frontend" object of metrics.json and of `vigil track`'s frontend.json: what the feature tracker did
// and, when the scene's geometry is known, how far its tracks are from the truth
// (frontend/frontend_evaluation.h).
//
//   {"features": "tracked", "images": .., "published_frames": .., "tracks": .., "observations": ..,
//    "tracker": {"klt_failures": .., "ransac_outliers": .., "spacing_drops": .., "outside_undistorted": ..,
//                "aged_out": .., "anchor_refined": .., "anchor_rejected": ..},
//    "track_length_frames": {"min": .., "median": .., "mean": .., "max": ..,
//                            "histogram": [{"from": 1, "to": 1, "count": ..}, ..., {"from": 100, "to": null,
//                            ..}]},
//    "reprojection": {"error_px": STATS, "evaluated": .., "first_observations": .., "without_truth": ..,
//                     "outlier_threshold_px": 2.0, "outliers": .., "outlier_ratio": ..,
//                     "error_by_age_px": [{"from": 1, "to": 1, "error_px": STATS}, ..., {"from": 100, "to":
//                     null,
//                                          ..}]}                                             (with a scene
//                                          only)
//    "time_per_image_ms": ..}                                                  (frontend.json only: timing)
// error_by_age_px groups the errors by the observation's age (frames since its track's first observation)
// over the bins of track_length_bins; a bin without observations has STATS of n = 0. STATS as everywhere
// (evaluation/statistics.h). Every number but the timing is a deterministic function of the images and the
// options.
#pragma once

#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/types.h"
#include "frontend/feature_tracker.h"
#include "frontend/frontend_evaluation.h"

namespace vigil::experiments {

nlohmann::json FrontendMetricsJson(const std::vector<CameraFrame>& frames,
                                   const frontend::TrackerStats& stats,
                                   const frontend::FrontendEvaluationOptions& options,
                                   const std::optional<frontend::ReprojectionEvaluation>& reprojection);

}  // namespace vigil::experiments
