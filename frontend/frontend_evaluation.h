// Evaluation of feature tracks: track lengths, and errors against true pixels (frontend/track_truth.h).
//
// Pure functions of the tracks (and the truth); what metrics.json's "frontend" key and `vigil track`'s
// frontend.json report (experiments/runs/frontend_metrics.h writes them).
//   - track length: published frames a track id appears in;
//   - reprojection error: |observed pixel - true pixel| of every observation that is not its track's first
//     (a first observation defines its track's scene point) and whose truth is known;
//   - outlier ratio: share of those observations with an error above outlier_threshold_px;
//   - the age of each evaluated observation: published frames since its track's first observation (1: the
//     track's second frame), so that errors can be told apart by how far a track has been carried (a
//     frame-to-frame tracker's error grows with it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/types.h"
#include "frontend/track_truth.h"

namespace vigil::frontend {

struct FrontendEvaluationOptions {
  double outlier_threshold_px = 2.0;
  // Lower edges of the track-length histogram's bins [frames], increasing; the last bin is open.
  std::vector<int> track_length_bins = {1, 2, 3, 5, 10, 20, 50, 100};

  template <class V>
  void Visit(V& v) {
    v.Field("outlier_threshold_px", outlier_threshold_px,
            "an observation farther than this from its true pixel is an outlier [px]",
            config::Bounds::Positive());
    v.Field("track_length_bins", track_length_bins,
            "lower edges of the track-length histogram bins [frames], increasing; the last bin is open",
            config::Bounds::AtLeast(1));
  }
};

// Checks what bounds cannot (bins strictly increasing, at least one); returns the reason or "".
std::string ValidateEvaluationOptions(const FrontendEvaluationOptions& options);

struct HistogramBin {
  int from = 0;  // frames, inclusive
  int to = -1;   // frames, inclusive; -1: open
  int64_t count = 0;
};

struct TrackLengthSummary {
  int64_t tracks = 0;
  int min = 0, max = 0;  // 0 without tracks
  double median = 0.0, mean = 0.0;
  std::vector<HistogramBin> histogram;
};

// The bin of `value` among bins with lower edges `bins` (increasing; the last bin is open): the last bin
// whose lower edge is <= value, or nothing when value is below the first edge.
std::optional<std::size_t> BinOf(const std::vector<int>& bins, int value);

// Lengths of every track id over `frames`, in the order of first appearance.
std::vector<int> TrackLengths(const std::vector<CameraFrame>& frames);
// Summary of `lengths` with the histogram of `bins` (lower edges; lengths below the first edge are counted in
// no bin).
TrackLengthSummary SummarizeTrackLengths(const std::vector<int>& lengths, const std::vector<int>& bins);

struct ReprojectionEvaluation {
  std::vector<double> errors_px;   // one per evaluated observation, in frame then feature order
  std::vector<int> ages_frames;    // beside errors_px: frames since the track's first observation (>= 1)
  int64_t observations = 0;        // every observation
  int64_t first_observations = 0;  // observations that start a track (not evaluated)
  int64_t without_truth = 0;       // later observations whose truth is unknown
  int64_t outliers = 0;            // evaluated observations with an error > threshold
  double outlier_ratio = 0.0;      // outliers / evaluated (0 when none was evaluated)
};

// `truth` has the shape of `frames` (ComputeTruePixels). Throws std::invalid_argument when it does not.
ReprojectionEvaluation EvaluateReprojection(const std::vector<CameraFrame>& frames, const TruePixels& truth,
                                            double outlier_threshold_px);

}  // namespace vigil::frontend
