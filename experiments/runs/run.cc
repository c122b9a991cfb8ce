#include "experiments/runs/run.h"

#include <chrono>
#include <exception>
#include <optional>
#include <string>
#include <utility>

#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/output.h"
#include "estimator/run_estimator.h"
#include "evaluation/evaluate_trajectory.h"
#include "experiments/runs/detection_stage.h"
#include "experiments/runs/external_estimator.h"
#include "experiments/runs/frontend_run.h"
#include "experiments/runs/imu_axis_record.h"
#include "experiments/runs/run_inputs.h"
#include "experiments/runs/run_metrics.h"
#include "sim/simulator.h"

namespace vigil::experiments {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The recording a run starts from, and what is known about it.
struct RunData {
  Dataset dataset;
  bool with_glitches = false;    // dataset.glitches is the truth (simulated, or glitches.csv present)
  bool with_clean = false;       // dataset.imu_clean is the glitch-free stream
  bool with_groundtruth = true;  // dataset.groundtruth is known (else the run is not evaluated)
  double duration_s = 0.0;
  std::optional<FrontendRunResult> frontend;  // when the tracker made the feature tracks
  std::vector<CameraImage> images;            // the recording's camera images (none when simulated)
  std::optional<EurocImuSensor> imu_sensor;   // the dataset's own mav0/imu0/sensor.yaml, when it has one
};

RunData LoadData(const RunConfig& config, const RunOptions& options) {
  RunData data;
  if (options.dataset_dir.empty()) {
    data.dataset = sim::Simulate(config.sim, config.seed);
    if (config.frontend.features == frontend::FeatureSource::kTracked)
      data.frontend = TrackSimulation(config, &data.dataset);
    data.with_glitches = data.with_clean = true;
    data.duration_s = config.sim.duration_s;
    return data;
  }
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(options.dataset_dir, ec))
    throw InputError(options.dataset_dir.string() + ": not a dataset directory");
  // A vigil dataset (with or without mav0/ images) or a EuRoC folder (core/euroc.h).
  Recording recording = ReadRecording(options.dataset_dir);
  if (!recording.has_camera)
    throw InputError(
        options.dataset_dir.string() +
        ": IMU only (no camera.yaml, no mav0/cam0/): vigil run needs a camera and its feature tracks "
        "(vigil clean works on IMU-only datasets)");
  // Tracks from the images when asked for, or when the recording has images but no features.csv.
  if (config.frontend.features == frontend::FeatureSource::kTracked ||
      (!recording.has_features && !recording.images.empty()))
    data.frontend = TrackRecording(config, options.dataset_dir, &recording);
  if (!recording.has_features)
    throw InputError(options.dataset_dir.string() +
                     ": no features.csv and no camera images (mav0/cam0/data.csv) to track");
  data.dataset = std::move(recording.dataset);
  data.images = std::move(recording.images);
  if (const fs::path mav0 = FindMav0(options.dataset_dir);
      !mav0.empty() && fs::is_regular_file(mav0 / euroc_files::kImu / euroc_files::kSensor, ec))
    data.imu_sensor = recording.imu_sensor;
  data.with_groundtruth = recording.has_groundtruth;
  data.with_glitches = fs::exists(options.dataset_dir / dataset_files::kGlitches, ec);
  data.with_clean = !data.dataset.imu_clean.empty();
  const ImuStream& imu = data.dataset.imu;
  data.duration_s = imu.size() > 1 ? NsToS(imu.back().t_ns - imu.front().t_ns) : 0.0;
  return data;
}

}  // namespace

estimator::EstimatorResult Estimate(const RunConfig& config, const Dataset& dataset, ImuStream imu,
                                    std::vector<uint8_t> flagged) {
  try {
    return estimator::RunEstimator(config.estimator,
                                   MakeEstimatorInput(config, dataset, std::move(imu), std::move(flagged)));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    estimator::EstimatorResult failed;
    failed.ok = false;
    failed.failure_reason = std::string("estimator error: ") + e.what();
    return failed;
  }
}

namespace {

// The glitched axis (the first of glitch.axes, a_z when none) as measured, clean and mitigated.
ImuAxisRecord ImuAxisRecordOf(const RunConfig& config, const RunData& data,
                              const detectors::DetectionResult& detection) {
  const ImuAxis axis = config.sim.glitch.axes.empty() ? ImuAxis::kAz : config.sim.glitch.axes.front();
  const bool with_clean = data.with_clean && data.dataset.imu_clean.size() == data.dataset.imu.size();
  return MakeImuAxisRecord(axis, data.dataset.imu, with_clean ? &data.dataset.imu_clean : nullptr,
                           detection.cleaned, detection.flagged);
}

}  // namespace

nlohmann::json ExecuteRun(const RunConfig& config, const RunOptions& options,
                          const std::filesystem::path& dir) {
  const Clock::time_point start = Clock::now();
  RunSummary summary;
  summary.seed = config.seed;
  summary.init = config.estimator.init;

  Clock::time_point t = Clock::now();
  const RunData data = LoadData(config, options);
  if (const std::string why = ExternalInputProblem(config, !data.images.empty(), true); !why.empty())
    throw InputError(options.dataset_dir.string() + ": " + why);
  summary.duration_s = data.duration_s;
  summary.wall.simulate_s = SecondsSince(t) - (data.frontend ? data.frontend->track_s : 0.0);

  t = Clock::now();
  // A recording calibrates on the clean reference the user names, never on a simulation it does not run.
  const std::optional<CalibrationReference> reference =
      options.dataset_dir.empty()
          ? std::nullopt
          : ResolveCalibrationReference(config, options.dataset_dir, data.dataset, data.with_clean,
                                        options.templates != nullptr);
  const CalibrationReference* reference_ptr = reference ? &*reference : nullptr;
  const auto templates = ResolveTemplates(config, options.templates, reference_ptr);
  summary.wall.templates_s = SecondsSince(t);
  t = Clock::now();
  DetectionStage detection =
      RunDetection(config, data.dataset, templates.get(), data.with_glitches, data.with_clean, reference_ptr);
  summary.wall.detect_s = SecondsSince(t);

  // What the figures draw, taken before the cleaned stream moves into the estimator.
  const std::string imu_axis_csv =
      options.write_figure_data ? ImuAxisCsv(ImuAxisRecordOf(config, data, detection.result)) : std::string();

  t = Clock::now();
  std::optional<ExternalEstimate> external;
  if (config.estimator.backend == EstimatorBackend::kExternal)
    external = RunExternalEstimator(config, data.dataset, detection.result.cleaned, detection.result.flagged,
                                    data.images, dir, data.imu_sensor ? &*data.imu_sensor : nullptr);
  const estimator::EstimatorResult result =
      external
          ? std::move(external->result)
          : Estimate(config, data.dataset, std::move(detection.result.cleaned), detection.result.flagged);
  summary.wall.estimate_s = SecondsSince(t);

  t = Clock::now();
  const Trajectory groundtruth = GroundTruthAtFrames(data.dataset.groundtruth, data.dataset.frames);
  evaluation::TrajectoryEvaluation evaluation =
      data.with_groundtruth
          ? evaluation::EvaluateTrajectory(groundtruth, result.trajectory, config.evaluation)
          : evaluation::TrajectoryEvaluation{};
  if (data.with_groundtruth)
    evaluation.nees = evaluation::ComputeNees(
        groundtruth, result.trajectory, result.pose_covariances,
        evaluation::GaugeAlignment(groundtruth, result.trajectory, result.pose_covariances));
  summary.wall.evaluate_s = SecondsSince(t);

  RunConfig resolved = config;  // ToYaml visits (non-const)
  WriteFileAtomic(dir / "config.yaml", config::ToYaml(resolved));
  if (options.write_trajectories) {
    if (data.with_groundtruth) WriteFileAtomic(dir / "stamped_groundtruth.txt", TumTrajectory(groundtruth));
    WriteFileAtomic(dir / "stamped_traj_estimate.txt", TumTrajectory(result.trajectory));
    if (config.detector.type != detectors::DetectorType::kNone)
      WriteFileAtomic(dir / "detections.csv",
                      detectors::DetectionsCsv(data.dataset.imu, detection.result.flagged));
  }
  if (options.write_figure_data) {
    WriteFileAtomic(dir / dataset_files::kLandmarks, LandmarksCsv(data.dataset.landmarks));
    WriteFileAtomic(dir / kImuAxisFile, imu_axis_csv);
  }
  summary.wall.total_s = SecondsSince(start);
  nlohmann::json metrics = RunMetricsJson(summary, result, evaluation, detection.json);
  if (!data.with_groundtruth) SkipEvaluation(result, &metrics);
  if (external) {
    metrics["external"] = external->json;
    DescribeExternalEstimator(&metrics);
  }
  if (data.frontend) {
    metrics["frontend"] = data.frontend->metrics;
    metrics["wall_time_s"]["track"] = data.frontend->track_s;  // rendering (simulated runs) and tracking
  }
  // A run from a recorded dataset names it, so that its figures show the recorded IMU (vigil plot run).
  if (!options.dataset_dir.empty())
    metrics["dataset"] = std::filesystem::absolute(options.dataset_dir).lexically_normal().string();
  WriteFileAtomic(dir / "metrics.json", metrics.dump(2) + "\n");
  return metrics;
}

}  // namespace vigil::experiments
