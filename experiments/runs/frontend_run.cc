#include "experiments/runs/frontend_run.h"

#include <chrono>
#include <memory>

#include "core/error.h"
#include "experiments/runs/frontend_metrics.h"
#include "experiments/runs/frontend_stage.h"
#include "sim/image_renderer.h"
#include "sim/scene.h"
#include "sim/simulator.h"
#include "sim/trajectory_model.h"

namespace vigil::experiments {
namespace {

using Clock = std::chrono::steady_clock;

frontend::RayCast MeshRayCast(const TriangleMesh& mesh) {
  return [&mesh](const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W) {
    return RayCast(mesh, origin_W, dir_W);
  };
}

nlohmann::json Evaluate(const RunConfig& config, const TrackedFeatures& tracked,
                        const std::vector<NavState>& groundtruth, const CameraModel& camera,
                        const TriangleMesh* mesh) {
  std::optional<frontend::ReprojectionEvaluation> reprojection;
  if (mesh && !groundtruth.empty())
    reprojection = EvaluateTracks(tracked.frames, groundtruth, camera, MeshRayCast(*mesh),
                                  config.frontend.evaluation.outlier_threshold_px);
  return FrontendMetricsJson(tracked.frames, tracked.stats, config.frontend.evaluation, reprojection);
}

}  // namespace

FrontendRunResult TrackSimulation(const RunConfig& config, Dataset* dataset) {
  const Clock::time_point start = Clock::now();
  const CameraModel& camera = dataset->camera;
  const std::unique_ptr<sim::TrajectoryModel> motion = sim::MakeTrajectoryModel(config.sim.trajectory);
  const sim::Scene scene = sim::ScenarioScene(config.sim, *motion);
  sim::ImageRenderer renderer(scene, camera, config.sim.images, config.seed);
  const std::vector<CameraFrame>& frames = dataset->frames;
  const auto image_at = [&](std::size_t k) -> std::pair<int64_t, cv::Mat> {
    std::vector<uint8_t> gray =
        renderer.Render(*motion, NsToS(frames[k].t_ns), config.sim.duration_s, static_cast<int>(k));
    return {frames[k].t_ns, cv::Mat(camera.height, camera.width, CV_8UC1, gray.data()).clone()};
  };
  const auto describe = [&](std::size_t k) { return "rendered frame " + std::to_string(k); };
  const TrackedFeatures tracked =
      TrackImages(frames.size(), image_at, describe, camera, config.frontend.tracker);
  const TriangleMesh mesh = scene.Mesh();
  FrontendRunResult result;
  result.metrics = Evaluate(config, tracked, dataset->groundtruth, camera, &mesh);
  dataset->frames = tracked.frames;
  result.track_s = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

FrontendRunResult TrackRecording(const RunConfig& config, const std::filesystem::path& dir,
                                 Recording* recording) {
  const Clock::time_point start = Clock::now();
  if (!recording->has_camera || recording->images.empty())
    throw InputError(dir.string() + ": frontend.features: tracked needs camera images (mav0/cam0/data.csv)");
  Dataset& dataset = recording->dataset;
  const TrackedFeatures tracked = TrackImageFiles(recording->images, dataset.camera, config.frontend.tracker);
  const std::optional<TriangleMesh> mesh = FindSceneMesh(dir);
  FrontendRunResult result;
  result.metrics =
      Evaluate(config, tracked, recording->has_groundtruth ? dataset.groundtruth : std::vector<NavState>{},
               dataset.camera, mesh ? &*mesh : nullptr);
  dataset.frames = tracked.frames;
  recording->has_features = true;
  result.track_s = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

std::optional<TriangleMesh> FindSceneMesh(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path clean = fs::absolute(dir).lexically_normal();
  if (!clean.has_filename()) clean = clean.parent_path();  // "mav0/"
  const fs::path root = clean.filename() == euroc_files::kMav0 ? clean.parent_path() : clean;
  const fs::path obj = root / kSceneObjFile;
  if (!fs::is_regular_file(obj, ec)) return std::nullopt;
  return ReadMeshObj(obj.string());
}

}  // namespace vigil::experiments
