#include "sim/camera_simulator.h"

#include "core/dataset.h"
#include "core/random.h"

namespace vigil::sim {

Eigen::Vector3d LandmarkInCamera(const CameraModel& camera, const Eigen::Quaterniond& q_WB,
                                 const Eigen::Vector3d& p_W, const Eigen::Vector3d& landmark_W) {
  const Eigen::Vector3d p_B = q_WB.conjugate() * (landmark_W - p_W);
  return camera.R_BC().transpose() * (p_B - camera.p_BC());
}

CameraFrame ObserveLandmarks(const CameraModel& camera, const Eigen::Quaterniond& q_WB,
                             const Eigen::Vector3d& p_W, const std::vector<Landmark>& landmarks, int64_t t_ns,
                             Rng* rng) {
  CameraFrame frame;
  frame.t_ns = t_ns;
  const bool distorted = camera.HasDistortion();
  for (const Landmark& l : landmarks) {
    const Eigen::Vector3d p_C = LandmarkInCamera(camera, q_WB, p_W, l.p_W);
    Eigen::Vector2d uv;
    if (!camera.Project(p_C, &uv)) continue;
    if (distorted && !camera.InImage(camera.DistortPixel(uv))) continue;
    if (camera.pixel_noise_px > 0.0) {
      const double du = rng->Normal(), dv = rng->Normal();
      uv += camera.pixel_noise_px * Eigen::Vector2d(du, dv);
    }
    frame.features.push_back({l.id, uv});
  }
  return frame;
}

std::vector<CameraFrame> SimulateFeatureTracks(const TrajectoryModel& motion, const CameraModel& camera,
                                               const std::vector<Landmark>& landmarks, int64_t t_first_ns,
                                               int64_t t_last_ns, uint64_t seed) {
  return SimulateFeatureTracksAt(motion, camera, landmarks,
                                 CameraFrameTimes(camera.rate_hz, t_first_ns, t_last_ns), seed);
}

std::vector<CameraFrame> SimulateFeatureTracksAt(const TrajectoryModel& motion, const CameraModel& camera,
                                                 const std::vector<Landmark>& landmarks,
                                                 const std::vector<int64_t>& times_ns, uint64_t seed) {
  Rng rng(seed, "pixels");
  std::vector<CameraFrame> frames;
  for (const int64_t t_ns : times_ns) {
    const TrajectoryState x = motion.StateAt(NsToS(t_ns));
    frames.push_back(ObserveLandmarks(camera, x.q_WB, x.p_W, landmarks, t_ns, &rng));
  }
  return frames;
}

}  // namespace vigil::sim
