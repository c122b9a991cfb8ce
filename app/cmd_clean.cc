// `vigil clean`: runs a detector + mitigation over an IMU CSV and writes the cleaned IMU, the per-sample
// flags and detection statistics (against glitches.csv / imu_clean.csv when they sit beside the input).
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/detector_args.h"
#include "core/config.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/output.h"
#include "detectors/detection_metrics.h"
#include "detectors/detector.h"
#include "detectors/dtw_detector.h"
#include "detectors/template_library.h"

namespace vigil::app {

void AddCleanCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "clean",
      "run a glitch detector + mitigation on DATASET/imu.csv (or DATASET/mav0/imu0/data.csv, "
      "or an imu0 CSV path); writes DIR/imu.csv, DIR/detections.csv, DIR/detection.json, DIR/config.yaml");
  struct Args {
    std::string dataset, output, detector, templates;
    DetectorArgs overrides;
    bool force = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("DATASET", args->dataset, "dataset directory (vigil or EuRoC) or EuRoC imu0 CSV file")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "output directory (must not exist or be empty, unless --force)")
      ->required();
  cmd->add_option("--detector", args->detector,
                  "detector: " + config::EnumChoices(detectors::DetectorTypeNames()))
      ->required();
  cmd->add_option("--templates", args->templates,
                  "DTW template library (from `vigil templates`); required for dtw");
  args->overrides.AddTo(cmd);
  cmd->add_flag("--force", args->force,
                "replace an output directory vigil wrote (files it did not write are kept)");
  SetAction(cmd, [args] {
    detectors::DetectorOptions options = args->overrides.Resolve();
    const auto type = config::EnumFromName(args->detector, detectors::DetectorTypeNames());
    if (!type) throw InputError("--detector: unknown detector '" + args->detector + "'");
    options.type = *type;
    if (!args->templates.empty()) options.dtw.templates_file = args->templates;

    // Read everything before writing anything.
    const ImuInput input = ResolveImuInput(args->dataset, dataset_files::kImu);
    const ImuStream raw = ReadImuCsv(input.imu.string());
    // A EuRoC imu0/ folder describes its IMU in sensor.yaml beside data.csv: checked like every input,
    // although cleaning needs none of it.
    if (const std::filesystem::path sensor = input.imu.parent_path() / euroc_files::kSensor;
        input.imu.filename() == euroc_files::kData && std::filesystem::exists(sensor))
      (void)ReadEurocImuSensorYaml(ReadTextFile(sensor.string(), 1 << 20));
    if (options.type == detectors::DetectorType::kThreshold &&
        options.threshold.calibration == detectors::ThresholdCalibration::kClean)
      throw InputError(
          "detector.threshold.calibration: clean calibrates on a simulation of a run's scenario; here set "
          "detector.threshold.calibration=manual and its lower/upper (`vigil templates OTHER_DATASET` prints "
          "calibrated ones)");
    std::unique_ptr<detectors::TemplateLibrary> library;
    if (options.type == detectors::DetectorType::kDtw) {
      if (options.dtw.templates_file.empty())
        throw InputError(
            "--templates: the dtw detector needs a template library built from clean data of another "
            "recording "
            "(`vigil templates OTHER_DATASET -o templates.yaml`); this input's imu_clean.csv is not used, it "
            "would leak the answer");
      library = std::make_unique<detectors::TemplateLibrary>(
          detectors::ReadTemplateLibrary(options.dtw.templates_file));
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path clean_path = input.dir / dataset_files::kImuClean;
    const fs::path glitches_path = input.dir / dataset_files::kGlitches;
    const bool has_clean = fs::exists(clean_path, ec), has_glitches = fs::exists(glitches_path, ec);
    ImuStream imu_clean;
    std::vector<GlitchRecord> glitches;
    if (has_clean) {
      imu_clean = ReadImuCsv(clean_path.string());
      CheckCleanImuMatches(raw, imu_clean, input.imu.string(), clean_path.string());
    }
    if (has_glitches) glitches = OffsetGlitches(ReadGlitchesCsv(glitches_path.string()));

    const detectors::DetectionResult result = detectors::DetectAndMitigate(options, raw, library.get());
    const detectors::DetectionMetrics metrics =
        detectors::EvaluateDetection(raw, result, glitches, imu_clean);

    nlohmann::json json;
    json["detector"] = args->detector;
    json["input"] = input.imu.string();
    if (library) {
      json["templates"] = options.dtw.templates_file;
      json["dtw_threshold"] = detectors::EffectiveDtwThreshold(options.dtw, *library);
    }
    json.update(detectors::DetectionJson(metrics, has_glitches, has_clean));

    // The dataset directory first (the clearest message), then every file read.
    std::vector<fs::path> inputs;
    if (fs::is_directory(args->dataset, ec)) inputs.emplace_back(args->dataset);
    for (const fs::path& file : {input.imu, clean_path, glitches_path, fs::path(options.dtw.templates_file)})
      inputs.push_back(file);
    RefuseOutputOverInputs(args->output, inputs);
    StagedDirectory out(args->output, args->force);
    WriteFileAtomic(out.path() / dataset_files::kImu,
                    ImuCsv(result.cleaned, (fs::path(args->output) / dataset_files::kImu).string()));
    WriteFileAtomic(out.path() / "detections.csv", detectors::DetectionsCsv(raw, result.flagged));
    WriteFileAtomic(out.path() / "config.yaml", DetectorConfigYaml(options));
    WriteFileAtomic(out.path() / "detection.json", json.dump(2) + "\n");
    out.Commit();
    std::fprintf(stderr, "vigil clean: %s flagged %lld of %lld samples in %lld segments",
                 args->detector.c_str(), static_cast<long long>(metrics.flagged_samples),
                 static_cast<long long>(metrics.samples), static_cast<long long>(metrics.flagged_segments));
    if (has_glitches)
      std::fprintf(stderr,
                   "; per sample: precision %.3f recall %.3f F1 %.3f false positives %.3f %%; per segment: "
                   "precision %.3f",
                   metrics.precision, metrics.recall, metrics.f1, 100.0 * metrics.false_positive_rate,
                   metrics.segment_precision);
    else
      std::fprintf(stderr, " (%.3f %%)",
                   metrics.samples > 0 ? 100.0 * static_cast<double>(metrics.flagged_samples) /
                                             static_cast<double>(metrics.samples)
                                       : 0.0);
    if (has_clean)
      std::fprintf(stderr, "; IMU RMS vs clean %.4g -> %.4g", metrics.imu_rmse_raw, metrics.imu_rmse_cleaned);
    std::fprintf(stderr, "\n");
    return 0;
  });
}

}  // namespace vigil::app
