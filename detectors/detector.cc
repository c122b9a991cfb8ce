#include "detectors/detector.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "core/csv.h"
#include "core/error.h"
#include "detectors/dtw_detector.h"
#include "detectors/hampel_detector.h"
#include "detectors/relative_threshold_detector.h"
#include "detectors/threshold_detector.h"

namespace vigil::detectors {
namespace {

// detector.type none: every sample passes unchanged and unflagged.
class PassThroughDetector final : public Detector {
 public:
  void Push(const ImuSample& raw, std::vector<DetectedSample>* out) override { out->push_back({raw, 0}); }
  void Finish(std::vector<DetectedSample>*) override {}
  int latency_samples() const override { return 0; }
};

}  // namespace

void ValidateDetectorOptions(const DetectorOptions& options) {
  const std::pair<const char*, std::size_t> per_axis[] = {
      {"detector.threshold.lower", options.threshold.lower.size()},
      {"detector.threshold.upper", options.threshold.upper.size()},
      {"detector.relative_threshold.bounds", options.relative_threshold.bounds.size()}};
  for (const auto& [key, axes] : per_axis)
    if (axes != static_cast<std::size_t>(kNumImuAxes))
      throw InputError(std::string(key) + ": expected 6 numbers (wx, wy, wz, ax, ay, az), got " +
                       std::to_string(axes));
  if (options.dtw.dims != 3 && options.dtw.dims != 6)
    throw InputError("detector.dtw.dims: must be 3 (acc) or 6 (acc + gyro), got " +
                     std::to_string(options.dtw.dims));
  if (options.dtw.template_length > options.dtw.slice_length)
    throw InputError("detector.dtw.template_length: must be <= detector.dtw.slice_length (" +
                     std::to_string(options.dtw.slice_length) + "), got " +
                     std::to_string(options.dtw.template_length));
}

std::unique_ptr<Detector> MakeDetector(const DetectorOptions& options, const TemplateLibrary* templates) {
  ValidateDetectorOptions(options);
  switch (options.type) {
    case DetectorType::kThreshold:
      return std::make_unique<ThresholdDetector>(options.threshold);
    case DetectorType::kRelativeThreshold:
      return std::make_unique<RelativeThresholdDetector>(options.relative_threshold);
    case DetectorType::kHampel:
      return std::make_unique<HampelDetector>(options.hampel);
    case DetectorType::kDtw:
      if (templates == nullptr)
        throw InputError(
            "detector.dtw: the dtw detector needs a template library (build one with `vigil templates`)");
      return std::make_unique<DtwDetector>(options.dtw, *templates);
    case DetectorType::kNone:
      break;
  }
  return std::make_unique<PassThroughDetector>();
}

DetectionResult DetectAndMitigate(const DetectorOptions& options, const ImuStream& raw,
                                  const TemplateLibrary* templates) {
  const std::unique_ptr<Detector> detector = MakeDetector(options, templates);
  std::vector<DetectedSample> out;
  out.reserve(raw.size());
  for (const ImuSample& s : raw) detector->Push(s, &out);
  detector->Finish(&out);
  DetectionResult result;
  result.cleaned.reserve(out.size());
  result.flagged.reserve(out.size());
  for (const DetectedSample& d : out) {
    result.cleaned.push_back(d.sample);
    result.flagged.push_back(d.flagged_axes != 0 ? 1 : 0);
  }
  return result;
}

std::string DetectionsCsv(const ImuStream& imu, const std::vector<uint8_t>& flagged) {
  if (imu.size() != flagged.size())
    throw std::invalid_argument("DetectionsCsv: one flag per sample expected");
  CsvWriter w("timestamp [ns],flagged", "detections.csv");
  for (std::size_t t = 0; t < imu.size(); ++t) {
    w << imu[t].t_ns << static_cast<int>(flagged[t] != 0);
    w.EndRow();
  }
  return w.Str();
}

}  // namespace vigil::detectors
