// `vigil track`: the visual front-end alone: a dataset's camera images -> feature tracks (features.csv), with
// the tracker's statistics and, for a rendered dataset, their errors against the scene (frontend.json).
#include <cstdio>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "core/config.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/euroc.h"
#include "core/output.h"
#include "experiments/frontend_metrics.h"
#include "experiments/frontend_run.h"
#include "experiments/frontend_stage.h"
#include "frontend/frontend_options.h"

namespace vigil::app {
namespace {

// The front-end's options as they sit in a run config, so that `--set frontend.max_features=200` reads the
// same here and config.yaml can be merged into one.
struct TrackConfig {
  frontend::FrontendOptions frontend;

  template <class V>
  void Visit(V& v) {
    v.Section("frontend", frontend, "visual front-end: feature tracks from camera images");
  }
};

}  // namespace

void AddTrackCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand(
      "track",
      "run the visual front-end (KLT tracker) on DATASET's camera images (EuRoC cam0 layout: a EuRoC folder "
      "or a dataset of `vigil simulate --images`); writes DIR/features.csv, DIR/frontend.json and "
      "DIR/config.yaml");
  struct Args {
    std::string dataset, output;
    std::vector<std::string> overrides;
    bool force = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("DATASET", args->dataset, "dataset directory with mav0/cam0 (EuRoC layout)")->required();
  cmd->add_option("-o,--output", args->output, "output directory (must not exist or be empty, unless --force)")
      ->required();
  cmd->add_option("--set", args->overrides, "override a front-end key: frontend.key=value (repeatable)")
      ->take_all();
  cmd->add_flag("--force", args->force, "replace an output directory vigil wrote (files it did not write are kept)");
  SetAction(cmd, [args] {
    TrackConfig config;
    for (const std::string& assignment : args->overrides) config::ApplyOverride(assignment, config);
    if (const std::string why = frontend::ValidateEvaluationOptions(config.frontend.evaluation); !why.empty())
      throw InputError("--set frontend.evaluation." + why);

    // Read and track everything before writing anything.
    const Recording recording = ReadRecording(args->dataset);
    if (!recording.has_camera || recording.images.empty())
      throw InputError(args->dataset + ": no camera images (expected mav0/cam0/data.csv and sensor.yaml)");
    const CameraModel& camera = recording.dataset.camera;
    const experiments::TrackedFeatures tracked =
        experiments::TrackImageFiles(recording.images, camera, config.frontend.tracker);
    std::optional<frontend::ReprojectionEvaluation> reprojection;
    const std::optional<TriangleMesh> scene = experiments::FindSceneMesh(args->dataset);
    if (scene && recording.has_groundtruth)
      reprojection = experiments::EvaluateTracks(
          tracked.frames, recording.dataset.groundtruth, camera,
          [&](const Eigen::Vector3d& o, const Eigen::Vector3d& d) { return RayCast(*scene, o, d); },
          config.frontend.evaluation.outlier_threshold_px);
    nlohmann::json json = experiments::FrontendMetricsJson(tracked.frames, tracked.stats,
                                                           config.frontend.evaluation, reprojection);
    json["dataset"] = std::filesystem::absolute(args->dataset).lexically_normal().string();
    json["time_per_image_ms"] =
        tracked.stats.images > 0 ? 1e3 * tracked.seconds / static_cast<double>(tracked.stats.images) : 0.0;

    RefuseOutputOverInputs(args->output, {args->dataset});
    StagedDirectory out(args->output, args->force);
    WriteFileAtomic(out.path() / dataset_files::kFeatures, FeaturesCsv(tracked.frames));
    WriteFileAtomic(out.path() / "frontend.json", json.dump(2) + "\n");
    WriteFileAtomic(out.path() / "config.yaml", config::ToYaml(config));
    out.Commit();

    std::fprintf(stderr, "vigil track: %lld images, %lld frames, %lld tracks (median length %.1f frames)",
                 static_cast<long long>(tracked.stats.images),
                 static_cast<long long>(tracked.stats.published_frames), json["tracks"].get<long long>(),
                 json["track_length_frames"]["median"].get<double>());
    if (reprojection)
      std::fprintf(stderr, "; reprojection error median %.3g px, %.2f %% above %.3g px",
                   json["reprojection"]["error_px"]["median"].is_number()
                       ? json["reprojection"]["error_px"]["median"].get<double>()
                       : 0.0,
                   100.0 * reprojection->outlier_ratio, config.frontend.evaluation.outlier_threshold_px);
    else
      std::fprintf(stderr, "; no %s", recording.has_groundtruth ? "scene geometry (scene.obj): no reprojection error"
                                                                : "ground truth: no reprojection error");
    std::fprintf(stderr, "; %.2f ms per image -> %s\n", json["time_per_image_ms"].get<double>(),
                 args->output.c_str());
    return 0;
  });
}

}  // namespace vigil::app
