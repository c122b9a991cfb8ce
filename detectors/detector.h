// Glitch detection and mitigation: one streaming interface for every detector.
//
// A Detector takes raw IMU samples one at a time (Push) and hands back, in input order, the same samples
// cleaned, each with the axes it flagged as abnormal. A detector may hold samples back, at most
// latency_samples() of them (threshold, relative_threshold: 0; Hampel: its half window; DTW: one slice minus
// one sample), so it runs on a live stream and on a file alike; Finish() releases what is held at the end of
// the stream. Every pushed sample comes out exactly once, with its timestamp unchanged.
//
// DetectAndMitigate() is the whole-stream convenience used by `vigil clean` and by runs.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/types.h"
#include "detectors/detector_options.h"

namespace vigil::detectors {

struct TemplateLibrary;

// One output sample: the (possibly mitigated) sample and a bit per flagged axis (bit i = imu.csv axis i,
// 0 = wx ... 5 = az; 0 = normal).
struct DetectedSample {
  ImuSample sample;
  uint8_t flagged_axes = 0;
};

class Detector {
 public:
  virtual ~Detector() = default;
  // Feeds the next raw sample (timestamps strictly increasing); appends the samples that are final to `out`.
  virtual void Push(const ImuSample& raw, std::vector<DetectedSample>* out) = 0;
  // End of stream: appends every sample still held.
  virtual void Finish(std::vector<DetectedSample>* out) = 0;
  // Largest number of samples held back between a Push and its output.
  virtual int latency_samples() const = 0;
};

// Cross-field checks of the detector options that key bounds cannot express (per-axis lists have 6 entries,
// dtw.dims is 3 or 6, dtw.template_length <= dtw.slice_length); InputError "detector.key: reason". Run config
// validation can call it; MakeDetector() does.
void ValidateDetectorOptions(const DetectorOptions& options);

// The detector `options.type` selects (kNone: a pass-through that flags nothing). `templates` is required for
// kDtw (InputError otherwise) and must outlive the detector; invalid options throw InputError.
std::unique_ptr<Detector> MakeDetector(const DetectorOptions& options,
                                       const TemplateLibrary* templates = nullptr);

struct DetectionResult {
  ImuStream cleaned;             // same length and timestamps as the input stream
  std::vector<uint8_t> flagged;  // one entry per input sample: 1 = flagged abnormal
};

// Whole-stream convenience over the streaming detectors. `templates` is required for dtw (else InputError).
DetectionResult DetectAndMitigate(const DetectorOptions& options, const ImuStream& raw,
                                  const TemplateLibrary* templates = nullptr);

// detections.csv (docs/formats.md): "#timestamp [ns],flagged" with one 0/1 row per sample of `imu`.
std::string DetectionsCsv(const ImuStream& imu, const std::vector<uint8_t>& flagged);

}  // namespace vigil::detectors
