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
    // The threshold detector calibrates on the same clean data: print its bounds as a ready --set.
    const std::vector<double> bounds = detectors::CalibrateThresholdBounds(clean, options.threshold);
    std::ostringstream set;
    for (std::size_t a = 0; a < bounds.size(); ++a) set << (a ? "," : "") << FormatDouble(bounds[a]);
    std::fprintf(stderr,
                 "vigil templates: threshold detector calibrated on the same data: --set "
                 "detector.threshold.bounds=[%s]\n",
                 set.str().c_str());
    return 0;
  });
}

}  // namespace vigil::app
