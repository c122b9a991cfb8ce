// `vigil clean` without the process: a detector + mitigation over a recording's IMU CSV, written as the
// cleaned IMU, the per-sample flags and the detection statistics (against glitches.csv / imu_clean.csv when
// they sit beside the input).
#pragma once

#include <string>
#include <vector>

#include "detectors/detection_metrics.h"

namespace vigil::experiments {

struct CleanRequest {
  std::string dataset;                 // a dataset directory (vigil or EuRoC) or an EuRoC imu0 CSV file
  std::string output;                  // the directory to write
  std::string detector;                // a detector name (detectors::DetectorTypeNames)
  std::string templates;               // DTW template library; empty: detector.dtw.templates_file
  std::vector<std::string> overrides;  // detector.key.path=value, applied in order to the defaults
  bool force = false;                  // replace an output directory vigil wrote
};

struct CleanResult {
  std::string detector;
  detectors::DetectionMetrics metrics;
  bool has_glitches = false, has_clean = false;  // whether glitches.csv / imu_clean.csv sat beside the input
};

// Reads and checks everything first (overrides, detector, the IMU and imu0/sensor.yaml, imu_clean.csv,
// glitches.csv, the template library): InputError "FILE:LINE: key: reason" with nothing written. Then writes
// into `output` (staged, refused over any input, and when not empty unless `force`):
//   imu.csv          the mitigated IMU
//   detections.csv   one flag per sample
//   detection.json   the detector, the input, the statistics (and the DTW library and threshold)
//   config.yaml      the detector options applied
// The paper's threshold detector must be calibrated by hand here (calibration manual): a recording has no
// scenario to simulate; dtw needs a template library of another recording.
CleanResult CleanRecording(const CleanRequest& request);

// The one line `vigil clean` reports (without "vigil clean: " and the newline): what was flagged, per-sample
// and per-segment precision and recall when glitches were known, the RMS difference to the clean IMU.
std::string CleanSummary(const CleanResult& result);

}  // namespace vigil::experiments
