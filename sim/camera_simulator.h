// Feature tracks seen by the simulated camera: ideal pinhole projections of the landmarks, plus optional
// Gaussian pixel noise.
//
// Frames are taken at core/dataset.h's CameraFrameTimes, or at given times (camera_timing.h). In a frame, a
// landmark is visible when its ideal projection (camera.Project of T_BC^-1 T_WB^-1 p_W) is in front of the
// camera and inside the image; its observation is that pixel plus N(0, pixel_noise_px^2) on u and v
// (stream "pixels"; a noisy pixel may leave the image by a fraction of a pixel). Observations are in landmark
// order; the track id is the landmark id.
#pragma once

#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "core/random.h"
#include "core/types.h"
#include "sim/trajectory_model.h"

namespace vigil::sim {

// Landmark position in the camera frame for the body pose (q_WB, p_W).
Eigen::Vector3d LandmarkInCamera(const CameraModel& camera, const Eigen::Quaterniond& q_WB,
                                 const Eigen::Vector3d& p_W, const Eigen::Vector3d& landmark_W);

// The observations of `landmarks` in one frame at t_ns from the body pose (q_WB, p_W), as described above
// (pixel noise drawn from `rng`, two draws per visible landmark). With lens distortion, a landmark is visible
// when both its pinhole pixel and its distorted (image) pixel lie inside the image.
CameraFrame ObserveLandmarks(const CameraModel& camera, const Eigen::Quaterniond& q_WB,
                             const Eigen::Vector3d& p_W, const std::vector<Landmark>& landmarks, int64_t t_ns,
                             Rng* rng);

// Tracks at CameraFrameTimes(camera.rate_hz, t_first_ns, t_last_ns).
std::vector<CameraFrame> SimulateFeatureTracks(const TrajectoryModel& motion, const CameraModel& camera,
                                               const std::vector<Landmark>& landmarks, int64_t t_first_ns,
                                               int64_t t_last_ns, uint64_t seed);
// Tracks at the given frame times (increasing, within the motion's span).
std::vector<CameraFrame> SimulateFeatureTracksAt(const TrajectoryModel& motion, const CameraModel& camera,
                                                 const std::vector<Landmark>& landmarks,
                                                 const std::vector<int64_t>& times_ns, uint64_t seed);

}  // namespace vigil::sim
