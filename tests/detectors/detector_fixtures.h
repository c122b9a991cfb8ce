// Set-ups shared by the detector tests: the options of one detector, the template library of the synthetic
// clean run, a synthetic run with glitches and its truth, and a stream pushed through a detector sample by
// sample.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "detectors/detection_metrics.h"
#include "detectors/detector.h"
#include "detectors/template_library.h"
#include "tests/detectors/synthetic_imu.h"

namespace vigil::detectors::testing {

// Detector options selecting `type` (every other option at its default), or one detector with its options.
inline DetectorOptions DetectorOf(DetectorType type) {
  DetectorOptions det;
  det.type = type;
  return det;
}
inline DetectorOptions DetectorOf(const ThresholdOptions& options) {
  DetectorOptions det = DetectorOf(DetectorType::kThreshold);
  det.threshold = options;
  return det;
}
inline DetectorOptions DetectorOf(const RelativeThresholdOptions& options) {
  DetectorOptions det = DetectorOf(DetectorType::kRelativeThreshold);
  det.relative_threshold = options;
  return det;
}
inline DetectorOptions DetectorOf(const HampelOptions& options) {
  DetectorOptions det = DetectorOf(DetectorType::kHampel);
  det.hampel = options;
  return det;
}

// Templates built on the clean synthetic run of seed 1000 (4001 samples), a seed no test judges on.
inline TemplateLibrary SyntheticTemplates(const DtwOptions& options = NormalizedDtw()) {
  return BuildTemplates(SyntheticImu(1000, 4001), options);
}

// The synthetic run of `seed` and a copy with N(mean, std) glitches on az at `rate` (InjectGlitches, same
// seed).
struct GlitchedRun {
  ImuStream clean;
  ImuStream raw;
  std::vector<GlitchRecord> glitches;
};
inline GlitchedRun Glitched(uint64_t seed, int samples, double mean, double std, double rate) {
  GlitchedRun run;
  run.clean = SyntheticImu(seed, samples);
  run.raw = run.clean;
  run.glitches = InjectGlitches(&run.raw, seed, mean, std, rate);
  return run;
}

// The detection metrics of `detector` on `run` (a DTW detector needs `library`).
inline DetectionMetrics Evaluate(const DetectorOptions& detector, const GlitchedRun& run,
                                 const TemplateLibrary* library = nullptr) {
  return EvaluateDetection(run.raw, DetectAndMitigate(detector, run.raw, library), run.glitches, run.clean);
}

// Pushes `imu` through `detector` one sample at a time and finishes it. Checks that the detector never holds
// more samples than its latency, and that it returns every sample once, in order, with its timestamp.
inline std::vector<DetectedSample> StreamThrough(Detector& detector, const ImuStream& imu) {
  std::vector<DetectedSample> out;
  for (std::size_t t = 0; t < imu.size(); ++t) {
    detector.Push(imu[t], &out);
    EXPECT_LE(static_cast<int>(t + 1 - out.size()), detector.latency_samples()) << "sample " << t;
  }
  detector.Finish(&out);
  EXPECT_EQ(out.size(), imu.size());
  for (std::size_t t = 0; t < std::min(out.size(), imu.size()); ++t)
    EXPECT_EQ(out[t].sample.t_ns, imu[t].t_ns) << "sample " << t;
  return out;
}

}  // namespace vigil::detectors::testing
