// `vigil templates`: builds a DTW template library (and calibrates the detection threshold) from clean IMU
// data.
#include <cstdio>
#include <memory>
#include <sstream>

#include "app/commands.h"
#include "app/detector_args.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/format.h"
#include "core/output.h"
#include "detectors/relative_threshold_detector.h"
#include "detectors/template_library.h"
#include "detectors/threshold_detector.h"

namespace vigil::app {

void AddTemplatesCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "templates",
      "build a DTW template library from clean IMU data: DATASET/imu_clean.csv (else DATASET/imu.csv) or an "
      "imu0 CSV path. Use data from another recording (another seed) than the one it will clean.");
  struct Args {
    std::string dataset, output;
    DetectorArgs detector;
    bool force = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("DATASET", args->dataset, "dataset directory or EuRoC imu0 CSV file")->required();
  cmd->add_option("-o,--output", args->output, "template library to write (YAML)")->required();
  args->detector.AddTo(cmd);
  cmd->add_flag("--force", args->force, "replace a template library vigil wrote");
  SetAction(cmd, [args] {
    const detectors::DetectorOptions options = args->detector.Resolve();
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool is_dir = fs::is_directory(args->dataset, ec);
    const std::string file_in_dir =
        is_dir && fs::exists(fs::path(args->dataset) / dataset_files::kImuClean, ec)
            ? dataset_files::kImuClean
            : dataset_files::kImu;
    const ImuInput input = ResolveImuInput(args->dataset, file_in_dir);
    RefuseOutputOverInputs(args->output, {input.imu, args->dataset});
    // Never rename over a device, directory or other special file (e.g. -o /dev/null), nor over a file
    // vigil did not write.
    RefuseReplacingFile(args->output, args->force, detectors::kTemplateLibraryFirstLine);
    const ImuStream clean = ReadImuCsv(input.imu.string());
    if (is_dir && file_in_dir == std::string(dataset_files::kImu))
      std::fprintf(stderr, "vigil templates: %s has no %s, using %s: it must be glitch-free\n",
                   args->dataset.c_str(), dataset_files::kImuClean, dataset_files::kImu);
    detectors::TemplateLibrary library;
    try {
      library = detectors::BuildTemplates(clean, options.dtw);
    } catch (const InputError& e) {
      throw InputError(input.imu.string() + ": " + e.what() +
                       " (use a longer clean recording or fewer detector.dtw.templates)");
    }
    library.source = input.imu.string();
    WriteFileAtomic(args->output, detectors::TemplateLibraryYaml(library));
    std::fprintf(stderr,
                 "vigil templates: %d templates of %d rows (d = %d) from %d slices of %d samples of %s; "
                 "threshold %s (%s x quantile %s = %s)\n",
                 library.count(), library.template_length, library.dims, library.calibration_slices,
                 library.slice_length, input.imu.c_str(), FormatDouble(library.threshold).c_str(),
                 FormatDouble(library.calibration_margin).c_str(),
                 FormatDouble(library.calibration_quantile).c_str(),
                 FormatDouble(library.calibration_quantile_distance).c_str());
    // The threshold detectors calibrate on the same clean data: print their bounds as a ready --set.
    const auto join = [](const std::vector<double>& values) {
      std::ostringstream out;
      for (std::size_t a = 0; a < values.size(); ++a) out << (a ? "," : "") << FormatDouble(values[a]);
      return out.str();
    };
    const detectors::ThresholdBounds bounds = detectors::CalibrateThresholdBounds(clean, options.threshold);
    std::fprintf(stderr,
                 "vigil templates: the paper's threshold detector calibrated on the same data (margin %s): "
                 "--set detector.threshold.calibration=manual --set detector.threshold.lower=[%s] --set "
                 "detector.threshold.upper=[%s]\n",
                 FormatDouble(options.threshold.calibration_margin).c_str(), join(bounds.lower).c_str(),
                 join(bounds.upper).c_str());
    std::fprintf(
        stderr,
        "vigil templates: vigil's relative threshold detector calibrated on the same data: --set "
        "detector.relative_threshold.bounds=[%s]\n",
        join(detectors::CalibrateRelativeThresholdBounds(clean, options.relative_threshold)).c_str());
    return 0;
  });
}

}  // namespace vigil::app
