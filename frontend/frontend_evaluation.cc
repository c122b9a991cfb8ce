#include "frontend/frontend_evaluation.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>

namespace vigil::frontend {

std::string ValidateEvaluationOptions(const FrontendEvaluationOptions& options) {
  if (options.track_length_bins.empty()) return "track_length_bins: needs at least one bin";
  for (std::size_t i = 1; i < options.track_length_bins.size(); ++i)
    if (options.track_length_bins[i] <= options.track_length_bins[i - 1])
      return "track_length_bins: must be strictly increasing";
  return "";
}

std::optional<std::size_t> BinOf(const std::vector<int>& bins, int value) {
  const auto it = std::upper_bound(bins.begin(), bins.end(), value);
  if (it == bins.begin()) return std::nullopt;
  return static_cast<std::size_t>(it - bins.begin()) - 1;
}

std::vector<int> TrackLengths(const std::vector<CameraFrame>& frames) {
  std::map<int, std::size_t> index;  // id -> position in `lengths`
  std::vector<int> lengths;
  for (const CameraFrame& frame : frames) {
    for (const FeatureObservation& obs : frame.features) {
      const auto [it, inserted] = index.emplace(obs.id, lengths.size());
      if (inserted) lengths.push_back(0);
      ++lengths[it->second];
    }
  }
  return lengths;
}

TrackLengthSummary SummarizeTrackLengths(const std::vector<int>& lengths, const std::vector<int>& bins) {
  TrackLengthSummary s;
  s.tracks = static_cast<int64_t>(lengths.size());
  for (std::size_t b = 0; b < bins.size(); ++b)
    s.histogram.push_back({bins[b], b + 1 < bins.size() ? bins[b + 1] - 1 : -1, 0});
  if (lengths.empty()) return s;
  std::vector<int> sorted = lengths;
  std::sort(sorted.begin(), sorted.end());
  s.min = sorted.front();
  s.max = sorted.back();
  const std::size_t n = sorted.size();
  s.median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  s.mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / static_cast<double>(n);
  for (int length : sorted)
    if (const std::optional<std::size_t> bin = BinOf(bins, length)) ++s.histogram[*bin].count;
  return s;
}

ReprojectionEvaluation EvaluateReprojection(const std::vector<CameraFrame>& frames, const TruePixels& truth,
                                            double outlier_threshold_px) {
  if (truth.size() != frames.size())
    throw std::invalid_argument("EvaluateReprojection: truth and frames differ in size");
  ReprojectionEvaluation e;
  std::map<int, std::size_t> first_frame;  // track id -> index of the frame of its first observation
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::vector<FeatureObservation>& features = frames[f].features;
    if (truth[f].size() != features.size())
      throw std::invalid_argument("EvaluateReprojection: truth and frame features differ in size");
    for (std::size_t i = 0; i < features.size(); ++i) {
      ++e.observations;
      const auto [first, inserted] = first_frame.emplace(features[i].id, f);
      if (inserted) {
        ++e.first_observations;
        continue;
      }
      if (!truth[f][i]) {
        ++e.without_truth;
        continue;
      }
      const double error = (features[i].uv_px - *truth[f][i]).norm();
      e.errors_px.push_back(error);
      e.ages_frames.push_back(static_cast<int>(f - first->second));
      if (error > outlier_threshold_px) ++e.outliers;
    }
  }
  if (!e.errors_px.empty())
    e.outlier_ratio = static_cast<double>(e.outliers) / static_cast<double>(e.errors_px.size());
  return e;
}

}  // namespace vigil::frontend
