#include "experiments/runs/frontend_metrics.h"

#include <optional>

#include "evaluation/statistics.h"

namespace vigil::experiments {
namespace {

// The errors of `reprojection` by age, over the bins whose lower edges are `bins` (the last bin open; ages
// below the first edge are in no bin).
nlohmann::json ErrorsByAgeJson(const frontend::ReprojectionEvaluation& reprojection,
                               const std::vector<int>& bins) {
  std::vector<std::vector<double>> errors_px(bins.size());
  for (std::size_t i = 0; i < reprojection.errors_px.size(); ++i)
    if (const std::optional<std::size_t> bin = frontend::BinOf(bins, reprojection.ages_frames[i]))
      errors_px[*bin].push_back(reprojection.errors_px[i]);
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t b = 0; b < bins.size(); ++b)
    out.push_back(
        {{"from", bins[b]},
         {"to", b + 1 < bins.size() ? nlohmann::json(bins[b + 1] - 1) : nlohmann::json(nullptr)},
         {"error_px", evaluation::StatisticsJson(evaluation::ComputeStatistics(std::move(errors_px[b])))}});
  return out;
}

}  // namespace

nlohmann::json FrontendMetricsJson(const std::vector<CameraFrame>& frames,
                                   const frontend::TrackerStats& stats,
                                   const frontend::FrontendEvaluationOptions& options,
                                   const std::optional<frontend::ReprojectionEvaluation>& reprojection) {
  const std::vector<int> lengths = frontend::TrackLengths(frames);
  const frontend::TrackLengthSummary summary =
      frontend::SummarizeTrackLengths(lengths, options.track_length_bins);
  int64_t observations = 0;
  for (const CameraFrame& frame : frames) observations += static_cast<int64_t>(frame.features.size());

  nlohmann::json j;
  j["features"] = "tracked";
  j["images"] = stats.images;
  j["published_frames"] = stats.published_frames;
  j["tracks"] = summary.tracks;
  j["observations"] = observations;
  j["tracker"] = {{"klt_failures", stats.klt_failures},
                  {"ransac_outliers", stats.ransac_outliers},
                  {"spacing_drops", stats.spacing_drops},
                  {"outside_undistorted", stats.outside_undistorted},
                  {"aged_out", stats.aged_out},
                  {"anchor_refined", stats.anchor_refined},
                  {"anchor_rejected", stats.anchor_rejected}};
  nlohmann::json histogram = nlohmann::json::array();
  for (const frontend::HistogramBin& bin : summary.histogram)
    histogram.push_back({{"from", bin.from},
                         {"to", bin.to < 0 ? nlohmann::json(nullptr) : nlohmann::json(bin.to)},
                         {"count", bin.count}});
  j["track_length_frames"] = {{"min", summary.min},
                              {"median", summary.median},
                              {"mean", summary.mean},
                              {"max", summary.max},
                              {"histogram", histogram}};
  if (reprojection) {
    j["reprojection"] = {
        {"error_px", evaluation::StatisticsJson(evaluation::ComputeStatistics(reprojection->errors_px))},
        {"evaluated", static_cast<int64_t>(reprojection->errors_px.size())},
        {"first_observations", reprojection->first_observations},
        {"without_truth", reprojection->without_truth},
        {"outlier_threshold_px", options.outlier_threshold_px},
        {"outliers", reprojection->outliers},
        {"outlier_ratio", reprojection->outlier_ratio},
        {"error_by_age_px", ErrorsByAgeJson(*reprojection, options.track_length_bins)}};
  }
  return j;
}

}  // namespace vigil::experiments
