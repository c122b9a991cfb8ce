#include "experiments/detection_stage.h"

#include <algorithm>

#include "core/config.h"
#include "core/random.h"
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

std::shared_ptr<const detectors::TemplateLibrary> ResolveTemplates(const RunConfig& config,
                                                                   const detectors::TemplateLibrary* given) {
  if (config.detector.type != detectors::DetectorType::kDtw) return nullptr;
  if (given) return std::shared_ptr<const detectors::TemplateLibrary>(given, [](const auto*) {});
  if (!config.detector.dtw.templates_file.empty())
    return std::make_shared<const detectors::TemplateLibrary>(
        detectors::ReadTemplateLibrary(config.detector.dtw.templates_file));
  return std::make_shared<const detectors::TemplateLibrary>(BuildTemplatesFromGlitchFreeSimulation(config));
}

detectors::ThresholdBounds CalibrateThresholdFromGlitchFreeSimulation(const RunConfig& config) {
  return detectors::CalibrateThresholdBounds(
      sim::SimulateImu(config.sim, DeriveSeed(config.seed, "calibration")).imu, config.detector.threshold);
}

detectors::DetectorOptions ResolveDetectorOptions(const RunConfig& config) {
  detectors::DetectorOptions options = config.detector;
  if (options.type == detectors::DetectorType::kThreshold &&
      options.threshold.calibration == detectors::ThresholdCalibration::kClean)
    options.threshold =
        detectors::WithBounds(options.threshold, CalibrateThresholdFromGlitchFreeSimulation(config));
  return options;
}

DetectionStage RunDetection(const RunConfig& config, const Dataset& dataset,
                            const detectors::TemplateLibrary* templates, bool with_glitches,
                            bool with_clean) {
  DetectionStage stage;
  const bool calibrate = config.detector.type == detectors::DetectorType::kThreshold &&
                         config.detector.threshold.calibration == detectors::ThresholdCalibration::kClean;
  const detectors::DetectorOptions options = ResolveDetectorOptions(config);
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
    stage.json["threshold_calibration"] = calibrate ? "glitch-free simulation, seed DeriveSeed(" +
                                                          std::to_string(config.seed) + ", \"calibration\")"
                                                    : std::string("manual");
  }
  if (templates) {
    stage.json["dtw_threshold"] = detectors::EffectiveDtwThreshold(config.detector.dtw, *templates);
    stage.json["templates_source"] = templates->source;
  }
  return stage;
}

}  // namespace vigil::experiments
