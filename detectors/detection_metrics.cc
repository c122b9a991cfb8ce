#include "detectors/detection_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vigil::detectors {

double ImuRmsDifference(const ImuStream& a, const ImuStream& b) {
  if (a.size() != b.size()) throw std::invalid_argument("ImuRmsDifference: streams of different lengths");
  if (a.empty()) return 0.0;
  double sum = 0.0;
  for (std::size_t t = 0; t < a.size(); ++t)
    sum += (a[t].w_B - b[t].w_B).squaredNorm() + (a[t].a_B - b[t].a_B).squaredNorm();
  return std::sqrt(sum / static_cast<double>(a.size()));
}

namespace {

double DetectionF1(double precision, double recall) {
  return precision + recall > 0 ? 2 * precision * recall / (precision + recall) : 0.0;
}

}  // namespace

DetectionMetrics EvaluateDetection(const ImuStream& raw, const DetectionResult& result,
                                   const std::vector<GlitchRecord>& glitches, const ImuStream& imu_clean) {
  const std::size_t n = raw.size();
  if (result.flagged.size() != n || result.cleaned.size() != n)
    throw std::invalid_argument("EvaluateDetection: the result does not have one entry per input sample");
  if (!imu_clean.empty() && imu_clean.size() != n)
    throw std::invalid_argument(
        "EvaluateDetection: the glitch-free stream (imu_clean.csv) has " + std::to_string(imu_clean.size()) +
        " samples, but the input (imu.csv) has " + std::to_string(n) +
        ": regenerate both together or remove imu_clean.csv (the dataset readers check this, "
        "core/dataset.h CheckCleanImuMatches)");

  std::vector<char> glitched(n, 0);
  for (const GlitchRecord& g : glitches) {
    const auto it = std::lower_bound(raw.begin(), raw.end(), g.t_ns,
                                     [](const ImuSample& s, int64_t t) { return s.t_ns < t; });
    if (it != raw.end() && it->t_ns == g.t_ns) glitched[it - raw.begin()] = 1;
  }

  DetectionMetrics m;
  m.samples = static_cast<int64_t>(n);
  int64_t false_flags = 0;
  for (std::size_t t = 0; t < n; ++t) {
    const bool flagged = result.flagged[t] != 0;
    m.flagged_samples += flagged;
    m.glitched_samples += glitched[t];
    m.detected_glitched_samples += flagged && glitched[t];
    false_flags += flagged && !glitched[t];
  }
  for (std::size_t t = 0; t < n;) {
    if (!result.flagged[t]) {
      ++t;
      continue;
    }
    bool contains_glitch = false;
    for (; t < n && result.flagged[t]; ++t) contains_glitch |= glitched[t] != 0;
    ++m.flagged_segments;
    m.true_segments += contains_glitch;
  }
  m.recall = m.glitched_samples > 0
                 ? static_cast<double>(m.detected_glitched_samples) / static_cast<double>(m.glitched_samples)
                 : 1.0;
  m.precision = m.flagged_samples > 0 ? static_cast<double>(m.detected_glitched_samples) /
                                            static_cast<double>(m.flagged_samples)
                                      : 1.0;
  m.segment_precision = m.flagged_segments > 0
                            ? static_cast<double>(m.true_segments) / static_cast<double>(m.flagged_segments)
                            : 1.0;
  m.f1 = DetectionF1(m.precision, m.recall);
  m.segment_f1 = DetectionF1(m.segment_precision, m.recall);
  const int64_t normal = m.samples - m.glitched_samples;
  m.false_positive_rate = normal > 0 ? static_cast<double>(false_flags) / static_cast<double>(normal) : 0.0;
  if (!imu_clean.empty()) {
    m.imu_rmse_raw = ImuRmsDifference(raw, imu_clean);
    m.imu_rmse_cleaned = ImuRmsDifference(result.cleaned, imu_clean);
  }
  return m;
}

nlohmann::json DetectionJson(const DetectionMetrics& m, bool with_glitches, bool with_clean) {
  nlohmann::json j;
  j["samples"] = m.samples;
  j["flagged_samples"] = m.flagged_samples;
  j["flagged_segments"] = m.flagged_segments;
  j["flagged_fraction"] =
      m.samples > 0 ? static_cast<double>(m.flagged_samples) / static_cast<double>(m.samples) : 0.0;
  if (with_glitches) {
    j["glitched_samples"] = m.glitched_samples;
    j["detected_glitched_samples"] = m.detected_glitched_samples;
    j["true_segments"] = m.true_segments;
    j["precision"] = m.precision;
    j["recall"] = m.recall;
    j["f1"] = m.f1;
    j["false_positive_rate"] = m.false_positive_rate;
    j["segment_precision"] = m.segment_precision;
    j["segment_f1"] = m.segment_f1;
  }
  if (with_clean) j["imu_rmse_vs_clean"] = {{"raw", m.imu_rmse_raw}, {"cleaned", m.imu_rmse_cleaned}};
  return j;
}

}  // namespace vigil::detectors
