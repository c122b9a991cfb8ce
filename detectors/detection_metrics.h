// How well a detector found the injected glitches, and how close its output is to the glitch-free IMU.
//
// Definitions (glitched sample = an input sample with at least one offset-kind row in glitches.csv, on any
// axis; the caller passes only offset records, core/dataset.h OffsetGlitches):
//   precision = flagged glitched samples / flagged samples (per sample: flagging every sample scores the
//               glitch fraction);
//   recall    = flagged glitched samples / glitched samples (per sample);
//   f1        = 2 precision recall / (precision + recall);
//   false_positive_rate = flagged samples that are not glitched / samples that are not glitched;
//   segment_precision = true segments / flagged segments, where a segment is a maximal run of consecutive
//               flagged samples and is true when it contains at least one glitched sample (a detector that
//               flags a whole DTW slice around one spike is one correct detection, not 39 false ones);
//   segment_f1 = 2 segment_precision recall / (segment_precision + recall).
// With no glitched sample recall is 1 (nothing to find); with no flagged sample both precisions are 1 (no
// false alarm). imu_rmse_* = sqrt(mean over samples of |x - x_clean|^2), the norm over all six axes (rad/s
// and m/s^2 mixed, as in imu.csv), before (raw) and after (cleaned) mitigation; 0 when imu_clean is empty.
#pragma once

#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/types.h"
#include "detectors/detector.h"

namespace vigil::detectors {

struct DetectionMetrics {
  int64_t flagged_samples = 0, glitched_samples = 0;
  double precision = 0, recall = 0, f1 = 0;       // per sample (definitions above)
  double imu_rmse_raw = 0, imu_rmse_cleaned = 0;  // RMS difference to imu_clean before/after mitigation
  int64_t samples = 0, flagged_segments = 0, true_segments = 0, detected_glitched_samples = 0;
  double false_positive_rate = 0;
  double segment_precision = 0, segment_f1 = 0;  // per flagged segment (definitions above)
};

// `result` must have one entry per `raw` sample; `imu_clean` is empty or the same length as `raw` (else
// std::invalid_argument). Glitch rows whose timestamp is not an input sample are ignored.
DetectionMetrics EvaluateDetection(const ImuStream& raw, const DetectionResult& result,
                                   const std::vector<GlitchRecord>& glitches, const ImuStream& imu_clean);

// RMS of |a_t - b_t| over all six axes (streams of equal length, else std::invalid_argument).
double ImuRmsDifference(const ImuStream& a, const ImuStream& b);

// The "detection" object of metrics.json / detection.json (docs/formats.md): sample and flag counts and
// flagged_fraction always; precision, recall, f1, false_positive_rate, segment_precision, segment_f1,
// glitched and true counts when `with_glitches`; "imu_rmse_vs_clean": {raw, cleaned} when
// `with_clean`.
nlohmann::json DetectionJson(const DetectionMetrics& metrics, bool with_glitches, bool with_clean);

}  // namespace vigil::detectors
