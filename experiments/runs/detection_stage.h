// The detection stage of a run: glitch detection + mitigation of the measured IMU, and how well it did.
//
// DTW needs a template library of normal motion. Its source, in order: the library the caller passes (a sweep
// builds one per setting and shares it), `detector.dtw.templates_file`, else a library built from the clean
// IMU of a glitch-free simulation of the same scenario with seed DeriveSeed(seed, "templates"): never from
// the run's own data, so the detector learns nothing about the glitches it is scored on. The paper's
// threshold detector with `detector.threshold.calibration: clean` likewise calibrates its bounds on a
// glitch-free simulation (seed DeriveSeed(seed, "calibration")).
//
// A run on a recording (`--dataset`) never calibrates on a simulation of a scenario it does not run: it
// calibrates on a CalibrationReference (below) or refuses.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/dataset.h"
#include "detectors/detection_metrics.h"
#include "detectors/detector.h"
#include "detectors/template_library.h"
#include "detectors/threshold_detector.h"
#include "experiments/runs/run_config.h"

namespace vigil::experiments {

// The glitch-free IMU a run on a recording calibrates its detector on, and where it came from.
struct CalibrationReference {
  ImuStream imu;
  std::string source;  // e.g. "imu_clean.csv of the recording", or the calibration dataset's file
};

// Whether the run's detector calibrates on clean data: threshold with calibration clean, or dtw with neither
// a templates file nor a library given by the caller.
bool NeedsCalibration(const RunConfig& config, bool templates_given);

// For a run on `recording_dir` (whose imu_clean.csv, when present, is `dataset.imu_clean`): the reference
// when NeedsCalibration, else nullopt. In order: detector.calibration_dataset (core/reference_imu.h), the
// recording's imu_clean.csv; else InputError saying what to give (the message of `vigil clean`).
std::optional<CalibrationReference> ResolveCalibrationReference(const RunConfig& config,
                                                                const std::filesystem::path& recording_dir,
                                                                const Dataset& dataset, bool with_clean,
                                                                bool templates_given);

// The library a dtw run uses (see above); null when the detector is not dtw. `given` may be null. The
// returned holder owns a library it read or built, or points at `given`. With a `reference` (a run on a
// recording) the library is built from reference->imu instead of a simulation.
std::shared_ptr<const detectors::TemplateLibrary> ResolveTemplates(
    const RunConfig& config, const detectors::TemplateLibrary* given,
    const CalibrationReference* reference = nullptr);

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

// config.detector as the run applies it: with calibrated threshold bounds when the above applies (on
// reference->imu when a reference is given).
detectors::DetectorOptions ResolveDetectorOptions(const RunConfig& config,
                                                  const CalibrationReference* reference = nullptr);

struct DetectionStage {
  detectors::DetectionResult result;  // cleaned IMU + one flag per sample
  detectors::DetectionMetrics metrics;
  nlohmann::json json;  // the "detection" object of metrics.json
};

// Runs config.detector on dataset.imu. `with_glitches` / `with_clean`: whether dataset.glitches and
// dataset.imu_clean are known (precision/recall and the RMS difference to the clean IMU are reported only
// then).
DetectionStage RunDetection(const RunConfig& config, const Dataset& dataset,
                            const detectors::TemplateLibrary* templates, bool with_glitches, bool with_clean,
                            const CalibrationReference* reference = nullptr);

}  // namespace vigil::experiments
