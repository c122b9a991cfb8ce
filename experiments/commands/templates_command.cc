#include "experiments/commands/templates_command.h"

#include <filesystem>
#include <sstream>

#include "core/dataset.h"
#include "core/error.h"
#include "core/format.h"
#include "core/imu_input.h"
#include "core/output.h"
#include "core/recording_files.h"
#include "detectors/detector_options.h"
#include "detectors/relative_threshold_detector.h"
#include "experiments/runs/run_config.h"

namespace vigil::experiments {
namespace {

namespace fs = std::filesystem;

std::string JoinDoubles(const std::vector<double>& values) {
  std::ostringstream out;
  for (std::size_t a = 0; a < values.size(); ++a) out << (a ? "," : "") << FormatDouble(values[a]);
  return out.str();
}

// The library, as `vigil templates` reports it.
std::string LibraryLine(const detectors::TemplateLibrary& library) {
  return FormatPrintf(
      "vigil templates: %d templates of %d rows (d = %d) from %d slices of %d samples of %s; "
      "threshold %s (%s x quantile %s = %s)\n",
      library.count(), library.template_length, library.dims, library.calibration_slices,
      library.slice_length, library.source.c_str(), FormatDouble(library.threshold).c_str(),
      FormatDouble(library.calibration_margin).c_str(), FormatDouble(library.calibration_quantile).c_str(),
      FormatDouble(library.calibration_quantile_distance).c_str());
}

// The threshold detectors' bounds calibrated on the same data, as ready --set options.
std::string BoundsLines(const TemplatesResult& result) {
  std::string text = FormatPrintf(
      "vigil templates: the paper's threshold detector calibrated on the same data (margin %s): "
      "--set detector.threshold.calibration=manual --set detector.threshold.lower=[%s] --set "
      "detector.threshold.upper=[%s]\n",
      FormatDouble(result.threshold_margin).c_str(), JoinDoubles(result.threshold_bounds.lower).c_str(),
      JoinDoubles(result.threshold_bounds.upper).c_str());
  text += FormatPrintf(
      "vigil templates: vigil's relative threshold detector calibrated on the same data: --set "
      "detector.relative_threshold.bounds=[%s]\n",
      JoinDoubles(result.relative_threshold_bounds).c_str());
  return text;
}

}  // namespace

TemplatesResult BuildTemplateLibraryFile(const TemplatesRequest& request) {
  auto section = DetectorSection();
  config::ApplyOverrides(request.overrides, section);
  const detectors::DetectorOptions& options = section.options;
  std::error_code ec;
  const bool is_dir = fs::is_directory(request.dataset, ec);
  const std::string file_in_dir =
      is_dir && fs::exists(fs::path(request.dataset) / dataset_files::kImuClean, ec)
          ? dataset_files::kImuClean
          : dataset_files::kImu;
  const ImuInput input = ResolveImuInput(request.dataset, file_in_dir);
  std::vector<fs::path> inputs = RecordingInputPaths(request.dataset);
  inputs.push_back(input.imu);
  RefuseOutputOverInputs(request.output, inputs);
  // Never rename over a device, directory or other special file (e.g. -o /dev/null), nor over a file
  // vigil did not write.
  RefuseReplacingFile(request.output, request.force, detectors::kTemplateLibraryFirstLine);
  const ImuStream clean = ReadImuCsv(input.imu.string());
  TemplatesResult result;
  result.used_imu_csv = is_dir && file_in_dir == std::string(dataset_files::kImu);
  if (result.used_imu_csv && request.report)
    request.report(FormatPrintf("vigil templates: %s has no %s, using %s: it must be glitch-free\n",
                                request.dataset.c_str(), dataset_files::kImuClean, dataset_files::kImu));
  try {
    result.library = detectors::BuildTemplates(clean, options.dtw);
  } catch (const InputError& e) {
    throw InputError(input.imu.string() + ": " + e.what() +
                     " (use a longer clean recording or fewer detector.dtw.templates)");
  }
  result.library.source = input.imu.string();
  WriteFileAtomic(request.output, detectors::TemplateLibraryYaml(result.library));
  if (request.report) request.report(LibraryLine(result.library));
  // The threshold detectors calibrate on the same clean data.
  result.threshold_margin = options.threshold.calibration_margin;
  result.threshold_bounds = detectors::CalibrateThresholdBounds(clean, options.threshold);
  result.relative_threshold_bounds =
      detectors::CalibrateRelativeThresholdBounds(clean, options.relative_threshold);
  if (request.report) request.report(BoundsLines(result));
  return result;
}

}  // namespace vigil::experiments
