// The visual front-end as a stage of a run or of `vigil track`: camera images -> feature tracks, and their
// evaluation against the true poses and the scene's geometry.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/euroc.h"
#include "core/types.h"
#include "frontend/feature_tracker.h"
#include "frontend/frontend_options.h"
#include "frontend/track_truth.h"

namespace vigil::experiments {

struct TrackedFeatures {
  std::vector<CameraFrame> frames;  // the published frames, in time order
  frontend::TrackerStats stats;
  double seconds = 0.0;  // wall time of tracking (image decoding excluded)
};

// Tracks `count` images given in time order by `image_at(i)` (timestamp, 8-bit grayscale image of the
// camera's size: InputError otherwise, with `describe(i)` naming the image).
TrackedFeatures TrackImages(std::size_t count,
                            const std::function<std::pair<int64_t, cv::Mat>(std::size_t)>& image_at,
                            const std::function<std::string(std::size_t)>& describe,
                            const CameraModel& camera, const frontend::FeatureTrackerOptions& options);

// Reads and tracks image files (cam0/data.csv rows; any format OpenCV reads, converted to 8-bit grayscale).
// A missing or unreadable file or one of another size than the camera's: InputError "LIST:LINE: PATH:
// reason".
TrackedFeatures TrackImageFiles(const std::vector<CameraImage>& images, const CameraModel& camera,
                                const frontend::FeatureTrackerOptions& options);

// The reprojection evaluation of `frames` against the true body poses `groundtruth` (interpolated at each
// frame; T_WC = T_WB T_BC) and the scene (`ray_cast` in W).
frontend::ReprojectionEvaluation EvaluateTracks(const std::vector<CameraFrame>& frames,
                                                const std::vector<NavState>& groundtruth,
                                                const CameraModel& camera, const frontend::RayCast& ray_cast,
                                                double outlier_threshold_px);

}  // namespace vigil::experiments
