// The detection stage of a run: glitch detection + mitigation of the measured IMU, and how well it did.
//
// DTW needs a template library of normal motion. Its source, in order: the library the caller passes (a sweep
// builds one per setting and shares it), `detector.dtw.templates_file`, else a library built from the clean
// IMU of a glitch-free simulation of the same scenario with seed DeriveSeed(seed, "templates"): never from
// the run's own data, so the detector learns nothing about the glitches it is scored on. The paper's
// threshold detector with `detector.threshold.calibration: clean` likewise calibrates its bounds on a
// glitch-free simulation (seed DeriveSeed(seed, "calibration")).
#pragma once

#include <cstdint>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/dataset.h"
#include "detectors/detection_metrics.h"
#include "detectors/detector.h"
#include "detectors/template_library.h"
#include "detectors/threshold_detector.h"
#include "experiments/run_config.h"

namespace vigil::experiments {

// The library a dtw run uses (see above); null when the detector is not dtw. `given` may be null. The
// returned holder owns a library it read or built, or points at `given`.
std::shared_ptr<const detectors::TemplateLibrary> ResolveTemplates(const RunConfig& config,
                                                                   const detectors::TemplateLibrary* given);

// The glitch-free simulation's library (the third source above): the run's scenario without glitches, seed
// DeriveSeed(seed, "templates"), lengthened when needed to at least 2 (k + 1) slices of clean IMU.
detectors::TemplateLibrary BuildTemplatesFromGlitchFreeSimulation(const RunConfig& config);

// The library of the clean IMU of `scenario` simulated with `seed` (its glitch settings play no part; only
// the IMU is simulated). Shared by single runs (above) and sweeps.
detectors::TemplateLibrary BuildTemplatesFromGlitchFreeSimulation(const sim::SimOptions& scenario,
                                                                  const detectors::DtwOptions& dtw,
                                                                  uint64_t seed);

// The paper's threshold detector with `calibration: clean`: bounds from the clean IMU of a glitch-free
// simulation of the run's scenario with seed DeriveSeed(seed, "calibration") (never the run's own data).
detectors::ThresholdBounds CalibrateThresholdFromGlitchFreeSimulation(const RunConfig& config);

// config.detector as the run applies it: with calibrated threshold bounds when the above applies.
detectors::DetectorOptions ResolveDetectorOptions(const RunConfig& config);

struct DetectionStage {
  detectors::DetectionResult result;  // cleaned IMU + one flag per sample
  detectors::DetectionMetrics metrics;
  nlohmann::json json;  // the "detection" object of metrics.json
};

// Runs config.detector on dataset.imu. `with_glitches` / `with_clean`: whether dataset.glitches and
// dataset.imu_clean are known (precision/recall and the RMS difference to the clean IMU are reported only
// then).
DetectionStage RunDetection(const RunConfig& config, const Dataset& dataset,
                            const detectors::TemplateLibrary* templates, bool with_glitches, bool with_clean);

}  // namespace vigil::experiments
