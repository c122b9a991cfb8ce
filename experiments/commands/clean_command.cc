#include "experiments/commands/clean_command.h"

#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/config.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/format.h"
#include "core/imu_input.h"
#include "core/output.h"
#include "core/recording_files.h"
#include "detectors/detector.h"
#include "detectors/dtw_detector.h"
#include "detectors/template_library.h"
#include "experiments/runs/run_config.h"

namespace vigil::experiments {
namespace {

namespace fs = std::filesystem;

// The detector options of the request: defaults, --set overrides, the detector and its template library.
detectors::DetectorOptions ResolveCleanOptions(const CleanRequest& request) {
  auto section = DetectorSection();
  config::ApplyOverrides(request.overrides, section);
  detectors::DetectorOptions options = section.options;
  const auto type = config::EnumFromName(request.detector, detectors::DetectorTypeNames());
  if (!type) throw InputError("--detector: unknown detector '" + request.detector + "'");
  options.type = *type;
  if (!request.templates.empty()) options.dtw.templates_file = request.templates;
  return options;
}

// The calibration a recording cannot give, and the library dtw needs (null for other detectors).
std::unique_ptr<detectors::TemplateLibrary> CheckCalibration(const detectors::DetectorOptions& options) {
  if (options.type == detectors::DetectorType::kThreshold &&
      options.threshold.calibration == detectors::ThresholdCalibration::kClean)
    throw InputError(
        "detector.threshold.calibration: clean calibrates on a simulation of a run's scenario; here set "
        "detector.threshold.calibration=manual and its lower/upper (`vigil templates OTHER_DATASET` prints "
        "calibrated ones)");
  if (options.type != detectors::DetectorType::kDtw) return nullptr;
  if (options.dtw.templates_file.empty())
    throw InputError(
        "--templates: the dtw detector needs a template library built from clean data of another "
        "recording "
        "(`vigil templates OTHER_DATASET -o templates.yaml`); this input's imu_clean.csv is not used, it "
        "would leak the answer");
  return std::make_unique<detectors::TemplateLibrary>(
      detectors::ReadTemplateLibrary(options.dtw.templates_file));
}

// Everything `vigil clean` reads, checked before anything is written.
struct CleanInputs {
  ImuInput input;
  ImuStream raw, imu_clean;
  std::vector<GlitchRecord> glitches;
  fs::path clean_path, glitches_path;
  bool has_clean = false, has_glitches = false;
};

CleanInputs ReadCleanInputs(const std::string& dataset) {
  CleanInputs in;
  in.input = ResolveImuInput(dataset, dataset_files::kImu);
  in.raw = ReadImuCsv(in.input.imu.string());
  // A EuRoC imu0/ folder describes its IMU in sensor.yaml beside data.csv: checked like every input,
  // although cleaning needs none of it.
  if (const fs::path sensor = in.input.imu.parent_path() / euroc_files::kSensor;
      in.input.imu.filename() == euroc_files::kData && fs::exists(sensor))
    (void)ReadEurocImuSensorYaml(ReadTextFile(sensor.string(), 1 << 20));
  return in;
}

// imu_clean.csv and glitches.csv beside the input, when there.
void ReadCleanReferences(CleanInputs* in) {
  std::error_code ec;
  in->clean_path = in->input.dir / dataset_files::kImuClean;
  in->glitches_path = in->input.dir / dataset_files::kGlitches;
  in->has_clean = fs::exists(in->clean_path, ec);
  in->has_glitches = fs::exists(in->glitches_path, ec);
  if (in->has_clean) {
    in->imu_clean = ReadImuCsv(in->clean_path.string());
    CheckCleanImuMatches(in->raw, in->imu_clean, in->input.imu.string(), in->clean_path.string());
  }
  if (in->has_glitches) in->glitches = OffsetGlitches(ReadGlitchesCsv(in->glitches_path.string()));
}

nlohmann::json CleanJson(const CleanRequest& request, const CleanInputs& in,
                         const detectors::DetectorOptions& options, const detectors::TemplateLibrary* library,
                         const detectors::DetectionMetrics& metrics) {
  nlohmann::json json;
  json["detector"] = request.detector;
  json["input"] = in.input.imu.string();
  if (library) {
    json["templates"] = options.dtw.templates_file;
    json["dtw_threshold"] = detectors::EffectiveDtwThreshold(options.dtw, *library);
  }
  json.update(detectors::DetectionJson(metrics, in.has_glitches, in.has_clean));
  return json;
}

void WriteCleanOutput(const CleanRequest& request, const CleanInputs& in,
                      const detectors::DetectorOptions& options, const detectors::DetectionResult& result,
                      const nlohmann::json& json) {
  // The dataset directory first (the clearest message), then every file read.
  std::vector<fs::path> inputs;
  std::error_code ec;
  if (fs::is_directory(request.dataset, ec)) inputs = RecordingInputPaths(request.dataset);
  for (const fs::path& file :
       {in.input.imu, in.clean_path, in.glitches_path, fs::path(options.dtw.templates_file)})
    inputs.push_back(file);
  RefuseOutputOverInputs(request.output, inputs);
  StagedDirectory out(request.output, request.force);
  WriteFileAtomic(out.path() / dataset_files::kImu,
                  ImuCsv(result.cleaned, (fs::path(request.output) / dataset_files::kImu).string()));
  WriteFileAtomic(out.path() / "detections.csv", detectors::DetectionsCsv(in.raw, result.flagged));
  auto section = DetectorSection();
  section.options = options;
  WriteFileAtomic(out.path() / "config.yaml", config::ToYaml(section));
  WriteFileAtomic(out.path() / "detection.json", json.dump(2) + "\n");
  out.Commit();
}

}  // namespace

CleanResult CleanRecording(const CleanRequest& request) {
  const detectors::DetectorOptions options = ResolveCleanOptions(request);
  // Read everything before writing anything.
  CleanInputs in = ReadCleanInputs(request.dataset);
  const std::unique_ptr<detectors::TemplateLibrary> library = CheckCalibration(options);
  ReadCleanReferences(&in);

  const detectors::DetectionResult result = detectors::DetectAndMitigate(options, in.raw, library.get());
  CleanResult clean{request.detector, detectors::EvaluateDetection(in.raw, result, in.glitches, in.imu_clean),
                    in.has_glitches, in.has_clean};
  WriteCleanOutput(request, in, options, result,
                   CleanJson(request, in, options, library.get(), clean.metrics));
  return clean;
}

std::string CleanSummary(const CleanResult& result) {
  const detectors::DetectionMetrics& m = result.metrics;
  std::string line =
      FormatPrintf("%s flagged %lld of %lld samples in %lld segments", result.detector.c_str(),
                   static_cast<long long>(m.flagged_samples), static_cast<long long>(m.samples),
                   static_cast<long long>(m.flagged_segments));
  if (result.has_glitches)
    line += FormatPrintf(
        "; per sample: precision %.3f recall %.3f F1 %.3f false positives %.3f %%; per segment: "
        "precision %.3f",
        m.precision, m.recall, m.f1, 100.0 * m.false_positive_rate, m.segment_precision);
  else
    line += FormatPrintf(" (%.3f %%)", m.samples > 0 ? 100.0 * static_cast<double>(m.flagged_samples) /
                                                           static_cast<double>(m.samples)
                                                     : 0.0);
  if (result.has_clean)
    line += FormatPrintf("; IMU RMS vs clean %.4g -> %.4g", m.imu_rmse_raw, m.imu_rmse_cleaned);
  return line;
}

}  // namespace vigil::experiments
