#include "experiments/runs/detection_stage.h"

#include <algorithm>

#include "core/config.h"
#include "core/error.h"
#include "core/random.h"
#include "core/reference_imu.h"
#include "detectors/dtw_detector.h"
#include "detectors/threshold_detector.h"
#include "sim/simulator.h"

namespace vigil::experiments {

detectors::TemplateLibrary BuildTemplatesFromGlitchFreeSimulation(const sim::SimOptions& scenario,
                                                                  const detectors::DtwOptions& dtw,
                                                                  uint64_t seed) {
  detectors::TemplateLibrary library = detectors::BuildTemplates(sim::SimulateImu(scenario, seed).imu, dtw);
  library.source = "glitch-free simulation, seed " + std::to_string(seed);
  return library;
}

// The longest such simulation stays within the simulator's limit, which would otherwise blame duration_s.
static_assert(2.0 * (detectors::kMaxDtwTemplates + 1) * detectors::kMaxDtwSliceSamples <=
              sim::kMaxImuSamples);

detectors::TemplateLibrary BuildTemplatesFromGlitchFreeSimulation(const RunConfig& config) {
  // A short run still gets a library: at least twice the k + 1 slices BuildTemplates needs.
  sim::SimOptions scenario = config.sim;
  const detectors::DtwOptions& dtw = config.detector.dtw;
  const double min_duration_s = 2.0 * (dtw.templates + 1) * dtw.slice_length / scenario.imu.rate_hz;
  scenario.duration_s = std::max(scenario.duration_s, min_duration_s);
  detectors::TemplateLibrary library =
      BuildTemplatesFromGlitchFreeSimulation(scenario, dtw, DeriveSeed(config.seed, "templates"));
  library.source =
      "glitch-free simulation, seed DeriveSeed(" + std::to_string(config.seed) + ", \"templates\")";
  return library;
}

bool NeedsCalibration(const RunConfig& config, bool templates_given) {
  const detectors::DetectorOptions& d = config.detector;
  return (d.type == detectors::DetectorType::kThreshold &&
          d.threshold.calibration == detectors::ThresholdCalibration::kClean) ||
         (d.type == detectors::DetectorType::kDtw && d.dtw.templates_file.empty() && !templates_given);
}

std::optional<CalibrationReference> ResolveCalibrationReference(const RunConfig& config,
                                                                const std::filesystem::path& recording_dir,
                                                                const Dataset& dataset, bool with_clean,
                                                                bool templates_given) {
  if (!NeedsCalibration(config, templates_given)) return std::nullopt;
  if (!config.detector.calibration_dataset.empty()) {
    ReferenceImu reference = ReadReferenceImu(config.detector.calibration_dataset);
    return CalibrationReference{std::move(reference.imu), reference.file.string()};
  }
  if (with_clean)
    return CalibrationReference{
        dataset.imu_clean, (recording_dir / dataset_files::kImuClean).string() + " (the recording's own)"};
  const std::string dir = recording_dir.string();
  if (config.detector.type == detectors::DetectorType::kThreshold)
    throw InputError("detector.threshold.calibration: clean calibrates on glitch-free data, and " + dir +
                     " has no imu_clean.csv; set detector.calibration_dataset=CLEAN_DATASET, or "
                     "detector.threshold.calibration=manual and its lower/upper (`vigil templates "
                     "OTHER_DATASET` prints calibrated ones)");
  throw InputError(
      "detector.dtw.templates_file: the dtw detector needs a template library built from clean "
      "data, and " +
      dir +
      " has no imu_clean.csv; set detector.dtw.templates_file (`vigil templates OTHER_DATASET -o "
      "templates.yaml`) or detector.calibration_dataset=CLEAN_DATASET");
}

std::shared_ptr<const detectors::TemplateLibrary> ResolveTemplates(const RunConfig& config,
                                                                   const detectors::TemplateLibrary* given,
                                                                   const CalibrationReference* reference) {
  if (config.detector.type != detectors::DetectorType::kDtw) return nullptr;
  if (given) return std::shared_ptr<const detectors::TemplateLibrary>(given, [](const auto*) {});
  if (!config.detector.dtw.templates_file.empty())
    return std::make_shared<const detectors::TemplateLibrary>(
        detectors::ReadTemplateLibrary(config.detector.dtw.templates_file));
  if (reference) {
    auto library = std::make_shared<detectors::TemplateLibrary>(
        detectors::BuildTemplates(reference->imu, config.detector.dtw));
    library->source = reference->source;
    return library;
  }
  return std::make_shared<const detectors::TemplateLibrary>(BuildTemplatesFromGlitchFreeSimulation(config));
}

detectors::ThresholdBounds CalibrateThresholdFromGlitchFreeSimulation(const RunConfig& config) {
  return detectors::CalibrateThresholdBounds(
      sim::SimulateImu(config.sim, DeriveSeed(config.seed, "calibration")).imu, config.detector.threshold);
}

detectors::DetectorOptions ResolveDetectorOptions(const RunConfig& config,
                                                  const CalibrationReference* reference) {
  detectors::DetectorOptions options = config.detector;
  if (options.type == detectors::DetectorType::kThreshold &&
      options.threshold.calibration == detectors::ThresholdCalibration::kClean)
    options.threshold = detectors::WithBounds(
        options.threshold, reference ? detectors::CalibrateThresholdBounds(reference->imu, options.threshold)
                                     : CalibrateThresholdFromGlitchFreeSimulation(config));
  return options;
}

DetectionStage RunDetection(const RunConfig& config, const Dataset& dataset,
                            const detectors::TemplateLibrary* templates, bool with_glitches, bool with_clean,
                            const CalibrationReference* reference) {
  DetectionStage stage;
  const bool calibrate = config.detector.type == detectors::DetectorType::kThreshold &&
                         config.detector.threshold.calibration == detectors::ThresholdCalibration::kClean;
  const detectors::DetectorOptions options = ResolveDetectorOptions(config, reference);
  stage.result = detectors::DetectAndMitigate(options, dataset.imu, templates);
  stage.metrics = detectors::EvaluateDetection(
      dataset.imu, stage.result,
      with_glitches ? OffsetGlitches(dataset.glitches) : std::vector<GlitchRecord>{},
      with_clean ? dataset.imu_clean : ImuStream{});
  stage.json = detectors::DetectionJson(stage.metrics, with_glitches, with_clean);
  stage.json["detector"] = config::EnumNameOf(config.detector.type, detectors::DetectorTypeNames());
  if (options.type == detectors::DetectorType::kThreshold) {
    stage.json["threshold_lower"] = options.threshold.lower;
    stage.json["threshold_upper"] = options.threshold.upper;
    stage.json["threshold_calibration"] =
        !calibrate ? std::string("manual")
        : reference
            ? reference->source
            : "glitch-free simulation, seed DeriveSeed(" + std::to_string(config.seed) + ", \"calibration\")";
  }
  if (templates) {
    stage.json["dtw_threshold"] = detectors::EffectiveDtwThreshold(config.detector.dtw, *templates);
    stage.json["templates_source"] = templates->source;
  }
  return stage;
}

}  // namespace vigil::experiments
