#include "detectors/detector.h"

#include <stdexcept>

#include "core/csv.h"
#include "core/error.h"
#include "detectors/dtw_detector.h"
#include "detectors/hampel_detector.h"
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

std::unique_ptr<Detector> MakeDetector(const DetectorOptions& options, const TemplateLibrary* templates) {
  switch (options.type) {
    case DetectorType::kThreshold:
      return std::make_unique<ThresholdDetector>(options.threshold);
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
  CsvWriter w("timestamp [ns],flagged");
  for (std::size_t t = 0; t < imu.size(); ++t) {
    w << imu[t].t_ns << static_cast<int>(flagged[t] != 0);
    w.EndRow();
  }
  return w.Str();
}

}  // namespace vigil::detectors
