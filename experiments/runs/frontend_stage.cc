#include "experiments/runs/frontend_stage.h"

#include <chrono>
#include <stdexcept>

#include "core/error.h"
#include "core/interpolation.h"
#include "core/output.h"
#include "frontend/gray_png.h"

namespace vigil::experiments {

TrackedFeatures TrackImages(std::size_t count,
                            const std::function<std::pair<int64_t, cv::Mat>(std::size_t)>& image_at,
                            const std::function<std::string(std::size_t)>& describe,
                            const CameraModel& camera, const frontend::FeatureTrackerOptions& options) {
  using Clock = std::chrono::steady_clock;
  TrackedFeatures out;
  frontend::FeatureTracker tracker(options, camera);
  for (std::size_t i = 0; i < count; ++i) {
    const auto [t_ns, image] = image_at(i);
    if (image.cols != camera.width || image.rows != camera.height)
      throw InputError(describe(i) + ": image of " + std::to_string(image.cols) + " x " +
                       std::to_string(image.rows) + " px, the camera's is " + std::to_string(camera.width) +
                       " x " + std::to_string(camera.height));
    if (image.type() != CV_8UC1) throw InputError(describe(i) + ": not an 8-bit grayscale image");
    const Clock::time_point start = Clock::now();
    std::optional<CameraFrame> frame;
    try {
      frame = tracker.Track(image, t_ns);
    } catch (const std::invalid_argument& e) {
      throw InputError(describe(i) + ": " + e.what());
    }
    out.seconds += std::chrono::duration<double>(Clock::now() - start).count();
    if (frame) out.frames.push_back(std::move(*frame));
  }
  out.stats = tracker.stats();
  return out;
}

TrackedFeatures TrackImageFiles(const std::vector<CameraImage>& images, const CameraModel& camera,
                                const frontend::FeatureTrackerOptions& options) {
  const auto describe = [&](std::size_t i) {
    const CameraImage& f = images[i];
    return f.list_path.empty() ? f.path : Located(f.list_path, f.list_line, f.path);
  };
  const auto load = [&](std::size_t i) -> std::pair<int64_t, cv::Mat> {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(images[i].path, ec))
      throw InputError(describe(i) + ": no such image file");
    cv::Mat image;
    try {
      image = frontend::DecodeGrayPng(ReadFile(images[i].path));
    } catch (const InputError& e) {
      throw InputError(describe(i) + ": " + e.what());
    }
    CheckImageSize(images[i], image.cols, image.rows, camera);
    return {images[i].t_ns, image};
  };
  return TrackImages(images.size(), load, describe, camera, options);
}

frontend::ReprojectionEvaluation EvaluateTracks(const std::vector<CameraFrame>& frames,
                                                const std::vector<NavState>& groundtruth,
                                                const CameraModel& camera, const frontend::RayCast& ray_cast,
                                                double outlier_threshold_px) {
  const Eigen::Isometry3d T_BC = camera.T_BC_iso();
  const frontend::CameraPoseAt pose_at = [&](int64_t t_ns) -> std::optional<Eigen::Isometry3d> {
    NavState state;
    if (!InterpolateNavState(groundtruth, t_ns, &state)) return std::nullopt;
    Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
    T_WB.linear() = state.q_WB.toRotationMatrix();
    T_WB.translation() = state.p_W;
    return T_WB * T_BC;
  };
  const frontend::PinholeIntrinsics intrinsics{camera.fx, camera.fy, camera.cx, camera.cy};
  return frontend::EvaluateReprojection(
      frames, frontend::ComputeTruePixels(frames, intrinsics, pose_at, ray_cast), outlier_threshold_px);
}

}  // namespace vigil::experiments
