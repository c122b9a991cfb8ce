// Re-running a run's detector on re-simulated IMU data (figure 5), since a run directory stores the flags
// (detections.csv) but not the mitigated signal.
//
// The simulator is deterministic, so Simulate(config.sim, config.seed) reproduces the run's raw IMU exactly.
// The DTW library is resolved as a run without a shared library resolves it (experiments/detection_stage.h:
// detector.dtw.templates_file, else a glitch-free simulation with seed DeriveSeed(seed, "templates"); the
// paper threshold's calibrated bounds likewise). A
// sweep that shared one library across runs may have used another one; the figure then shades the flags the
// run recorded and overlays the re-run's mitigation.
#pragma once

#include "core/types.h"
#include "detectors/detector.h"
#include "experiments/run_config.h"

namespace vigil::plots {

detectors::DetectionResult ReplayDetection(const experiments::RunConfig& config, const ImuStream& raw);

}  // namespace vigil::plots
