#include "plots/detection_replay.h"

#include "experiments/detection_stage.h"

namespace vigil::plots {

detectors::DetectionResult ReplayDetection(const experiments::RunConfig& config, const ImuStream& raw) {
  const auto templates = experiments::ResolveTemplates(config, nullptr);
  return detectors::DetectAndMitigate(experiments::ResolveDetectorOptions(config), raw, templates.get());
}

}  // namespace vigil::plots
