#include "experiments/detection_stage.h"

#include "core/random.h"
#include "sim/simulator.h"

namespace vigil::experiments {

detectors::TemplateLibrary BuildTemplatesFromGlitchFreeSimulation(const RunConfig& config) {
  sim::SimOptions clean_sim = config.sim;
  clean_sim.glitch.enabled = false;
  const Dataset clean = sim::Simulate(clean_sim, DeriveSeed(config.seed, "templates"));
  detectors::TemplateLibrary library =
      detectors::BuildTemplates(clean.imu_clean.empty() ? clean.imu : clean.imu_clean, config.detector.dtw);
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

DetectionStage RunDetection(const RunConfig& config, const Dataset& dataset,
                            const detectors::TemplateLibrary* templates, bool with_glitches,
                            bool with_clean) {
  DetectionStage stage;
  stage.result = detectors::DetectAndMitigate(config.detector, dataset.imu, templates);
  stage.metrics = detectors::EvaluateDetection(dataset.imu, stage.result,
                                               with_glitches ? dataset.glitches : std::vector<GlitchRecord>{},
                                               with_clean ? dataset.imu_clean : ImuStream{});
  stage.json = detectors::DetectionJson(stage.metrics, with_glitches, with_clean);
  for (const auto& [name, type] : detectors::DetectorTypeNames())
    if (type == config.detector.type) stage.json["detector"] = name;
  if (templates) {
    stage.json["dtw_threshold"] =
        config.detector.dtw.threshold > 0 ? config.detector.dtw.threshold : templates->threshold;
    stage.json["templates_source"] = templates->source;
  }
  return stage;
}

}  // namespace vigil::experiments
