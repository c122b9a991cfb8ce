#include "frontend/track_truth.h"

#include <map>

namespace vigil::frontend {

TruePixels ComputeTruePixels(const std::vector<CameraFrame>& frames, const PinholeIntrinsics& intrinsics,
                             const CameraPoseAt& T_WC_at, const RayCast& ray_cast) {
  constexpr double kMinDepth_m = 1e-6;
  // The scene point of each track (nothing: unknown), fixed by its first observation.
  std::map<int, std::optional<Eigen::Vector3d>> points_W;
  TruePixels truth(frames.size());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const CameraFrame& frame = frames[f];
    truth[f].resize(frame.features.size());
    const std::optional<Eigen::Isometry3d> T_WC = T_WC_at(frame.t_ns);
    for (std::size_t i = 0; i < frame.features.size(); ++i) {
      const FeatureObservation& obs = frame.features[i];
      const auto it = points_W.find(obs.id);
      if (it == points_W.end()) {
        std::optional<Eigen::Vector3d>& p_W = points_W[obs.id];
        if (!T_WC) continue;
        const Eigen::Vector3d ray_C((obs.uv_px.x() - intrinsics.cx) / intrinsics.fx,
                                    (obs.uv_px.y() - intrinsics.cy) / intrinsics.fy, 1.0);
        const Eigen::Vector3d dir_W = (T_WC->linear() * ray_C).normalized();
        const std::optional<double> distance = ray_cast(T_WC->translation(), dir_W);
        if (!distance) continue;
        p_W = T_WC->translation() + *distance * dir_W;
        truth[f][i] = obs.uv_px;
        continue;
      }
      if (!it->second || !T_WC) continue;
      const Eigen::Vector3d p_C = T_WC->inverse() * *it->second;
      if (p_C.z() <= kMinDepth_m) continue;
      truth[f][i] = Eigen::Vector2d(intrinsics.fx * p_C.x() / p_C.z() + intrinsics.cx,
                                    intrinsics.fy * p_C.y() / p_C.z() + intrinsics.cy);
    }
  }
  return truth;
}

}  // namespace vigil::frontend
