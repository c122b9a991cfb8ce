#include "experiments/commands/track_command.h"

#include <filesystem>

#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/format.h"
#include "core/output.h"
#include "core/recording_files.h"
#include "experiments/runs/frontend_metrics.h"
#include "experiments/runs/frontend_run.h"
#include "experiments/runs/frontend_stage.h"
#include "experiments/runs/run_config.h"
#include "frontend/frontend_options.h"

namespace vigil::experiments {
namespace {

config::ConfigSection<frontend::FrontendOptions> ResolveTrackOptions(
    const std::vector<std::string>& overrides) {
  auto section = FrontendSection();
  config::ApplyOverrides(overrides, section);
  if (const std::string why = frontend::ValidateEvaluationOptions(section.options.evaluation); !why.empty())
    throw InputError("--set frontend.evaluation." + why);
  return section;
}

// The reprojection errors of `frames` against the scene and the ground truth, when the dataset has both.
std::optional<frontend::ReprojectionEvaluation> EvaluateAgainstScene(const std::string& dataset,
                                                                     const Recording& recording,
                                                                     const std::vector<CameraFrame>& frames,
                                                                     double outlier_threshold_px) {
  const std::optional<TriangleMesh> scene = FindSceneMesh(dataset);
  if (!scene || !recording.has_groundtruth) return std::nullopt;
  return EvaluateTracks(
      frames, recording.dataset.groundtruth, recording.dataset.camera,
      [&](const Eigen::Vector3d& o, const Eigen::Vector3d& d) { return RayCast(*scene, o, d); },
      outlier_threshold_px);
}

}  // namespace

TrackResult TrackToDirectory(const TrackRequest& request) {
  auto section = ResolveTrackOptions(request.overrides);
  const frontend::FrontendOptions& options = section.options;
  // Read and track everything before writing anything.
  const Recording recording = ReadRecording(request.dataset);
  if (!recording.has_camera || recording.images.empty())
    throw InputError(request.dataset + ": no camera images (expected mav0/cam0/data.csv and sensor.yaml)");
  const TrackedFeatures tracked =
      TrackImageFiles(recording.images, recording.dataset.camera, options.tracker);
  const std::optional<frontend::ReprojectionEvaluation> reprojection = EvaluateAgainstScene(
      request.dataset, recording, tracked.frames, options.evaluation.outlier_threshold_px);
  TrackResult result;
  result.frontend = FrontendMetricsJson(tracked.frames, tracked.stats, options.evaluation, reprojection);
  result.frontend["dataset"] = std::filesystem::absolute(request.dataset).lexically_normal().string();
  result.frontend["time_per_image_ms"] =
      tracked.stats.images > 0 ? 1e3 * tracked.seconds / static_cast<double>(tracked.stats.images) : 0.0;
  result.has_groundtruth = recording.has_groundtruth;
  if (reprojection) result.outlier_ratio = reprojection->outlier_ratio;
  result.outlier_threshold_px = options.evaluation.outlier_threshold_px;

  RefuseOutputOverInputs(request.output, RecordingInputPaths(request.dataset));
  StagedDirectory out(request.output, request.force);
  WriteFileAtomic(out.path() / dataset_files::kFeatures, FeaturesCsv(tracked.frames));
  WriteFileAtomic(out.path() / "frontend.json", result.frontend.dump(2) + "\n");
  WriteFileAtomic(out.path() / "config.yaml", config::ToYaml(section));
  out.Commit();
  return result;
}

std::string TrackSummary(const TrackRequest& request, const TrackResult& result) {
  const nlohmann::json& json = result.frontend;
  std::string line =
      FormatPrintf("%lld images, %lld frames, %lld tracks (median length %.1f frames)",
                   json["images"].get<long long>(), json["published_frames"].get<long long>(),
                   json["tracks"].get<long long>(), json["track_length_frames"]["median"].get<double>());
  if (result.outlier_ratio) {
    const nlohmann::json& median = json["reprojection"]["error_px"]["median"];
    line += FormatPrintf("; reprojection error median %.3g px, %.2f %% above %.3g px",
                         median.is_number() ? median.get<double>() : 0.0, 100.0 * *result.outlier_ratio,
                         result.outlier_threshold_px);
  } else {
    line +=
        FormatPrintf("; no %s", result.has_groundtruth ? "scene geometry (scene.obj): no reprojection error"
                                                       : "ground truth: no reprojection error");
  }
  return line + FormatPrintf("; %.2f ms per image -> %s", json["time_per_image_ms"].get<double>(),
                             request.output.c_str());
}

}  // namespace vigil::experiments
