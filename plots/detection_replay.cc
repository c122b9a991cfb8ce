#include "plots/detection_replay.h"

#include "core/random.h"
#include "detectors/template_library.h"
#include "sim/simulator.h"

namespace vigil::plots {

detectors::DetectionResult ReplayDetection(const experiments::RunConfig& config, const ImuStream& raw) {
  if (config.detector.type != detectors::DetectorType::kDtw) {
    return detectors::DetectAndMitigate(config.detector, raw);
  }
  detectors::TemplateLibrary library;
  if (!config.detector.dtw.templates_file.empty()) {
    library = detectors::ReadTemplateLibrary(config.detector.dtw.templates_file);
  } else {
    sim::SimOptions clean = config.sim;
    clean.glitch.enabled = false;
    const Dataset data = sim::Simulate(clean, DeriveSeed(config.seed, "templates"));
    library =
        detectors::BuildTemplates(data.imu_clean.empty() ? data.imu : data.imu_clean, config.detector.dtw);
  }
  return detectors::DetectAndMitigate(config.detector, raw, &library);
}

}  // namespace vigil::plots
