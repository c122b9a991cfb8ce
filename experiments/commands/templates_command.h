// `vigil templates` without the process: a DTW template library (and its calibrated threshold) built from
// clean IMU data, and the threshold detectors' bounds calibrated on the same data.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/types.h"
#include "detectors/template_library.h"
#include "detectors/threshold_detector.h"

namespace vigil::experiments {

struct TemplatesRequest {
  std::string dataset;  // a dataset directory (its imu_clean.csv, else imu.csv) or an EuRoC imu0 CSV file
  std::string output;   // the template library to write (YAML)
  std::vector<std::string> overrides;  // detector.key.path=value, applied in order to the defaults
  bool force = false;                  // replace a template library vigil wrote
  // Told each line of the report ("vigil templates: ...\n") when it is known: a warning before the build,
  // then the library and the calibrated bounds as ready --set options. May be empty.
  std::function<void(const std::string&)> report;
};

struct TemplatesResult {
  detectors::TemplateLibrary library;
  bool used_imu_csv = false;      // a dataset directory without imu_clean.csv: its imu.csv was taken as clean
  double threshold_margin = 0.0;  // of the paper's threshold detector
  detectors::ThresholdBounds threshold_bounds;    // the paper's threshold detector, on the same data
  std::vector<double> relative_threshold_bounds;  // vigil's relative threshold detector, on the same data
};

// Refuses an output that is (or lies inside) an input, is not a regular file, or is a file vigil did not
// write (unless `force` and a template library), before reading; InputError for bad data (with the advice
// to use a longer recording or fewer templates). Writes the library atomically.
TemplatesResult BuildTemplateLibraryFile(const TemplatesRequest& request);

}  // namespace vigil::experiments
