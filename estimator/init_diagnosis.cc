#include "estimator/init_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "core/format.h"

namespace vigil::estimator {
namespace {

// Tracks a reference frame must share with a later one for their displacement to count.
constexpr int kMinSharedTracks = 5;

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Standard deviation of each axis of `get` over samples [first, last], as the norm of the three.
template <class Get>
double AxisStdNorm(const ImuStream& imu, std::size_t first, std::size_t last, Get get) {
  if (last < first + 1) return 0.0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum_sq = Eigen::Vector3d::Zero();
  for (std::size_t k = first; k <= last; ++k) {
    const Eigen::Vector3d x = get(imu[k]);
    sum += x;
    sum_sq += x.cwiseProduct(x);
  }
  const double n = static_cast<double>(last - first + 1);
  const Eigen::Vector3d mean = sum / n;
  return (sum_sq / n - mean.cwiseProduct(mean)).cwiseMax(0.0).cwiseSqrt().norm();
}

}  // namespace

InitEvidence MeasureInitEvidence(const EstimatorInput& input, const ImuStream& imu) {
  InitEvidence e;
  if (imu.size() < 2) return e;
  const double fx = input.camera.fx;
  const std::map<int, Eigen::Vector2d>* reference = nullptr;  // uv_px by id of the reference frame
  std::map<int, Eigen::Vector2d> reference_uv;
  int64_t first_t = 0, last_t = 0;
  for (const CameraFrame& frame : input.frames) {
    if (frame.t_ns < imu.front().t_ns || frame.t_ns > imu.back().t_ns) continue;
    if (e.frames++ == 0) first_t = frame.t_ns;
    last_t = frame.t_ns;
    e.max_features = std::max(e.max_features, static_cast<int>(frame.features.size()));
    std::map<int, Eigen::Vector2d> uv;
    for (const FeatureObservation& obs : frame.features) uv[obs.id] = input.camera.Normalize(obs.uv_px);
    std::vector<double> moved_px;
    if (reference) {
      for (const auto& [id, x] : uv) {
        const auto it = reference->find(id);
        if (it != reference->end()) moved_px.push_back(fx * (x - it->second).norm());
      }
    }
    if (static_cast<int>(moved_px.size()) >= kMinSharedTracks) {
      e.max_displacement_px = std::max(e.max_displacement_px, Median(moved_px));
    } else if (static_cast<int>(uv.size()) >= kMinSharedTracks) {
      reference_uv = std::move(uv);  // tracks renewed: measure from here on
      reference = &reference_uv;
    }
  }
  e.span_s = NsToS(last_t - first_t);
  const auto at = [&](int64_t t) {
    return static_cast<std::size_t>(
        std::lower_bound(imu.begin(), imu.end(), t,
                         [](const ImuSample& s, int64_t v) { return s.t_ns < v; }) -
        imu.begin());
  };
  if (e.frames > 0) {
    const std::size_t first = at(first_t), last = std::min(at(last_t), imu.size() - 1);
    e.gyro_std_radps = AxisStdNorm(imu, first, last, [](const ImuSample& s) { return s.w_B; });
    e.accel_std_mps2 = AxisStdNorm(imu, first, last, [](const ImuSample& s) { return s.a_B; });
  }
  return e;
}

std::string DiagnoseNoInitialization(const EstimatorOptions& options, const InitEvidence& e,
                                     int window_frames, const std::string& last_attempt) {
  const std::string motion = "features moved at most " + FormatFixed(e.max_displacement_px, 2) + " px in " +
                             FormatFixed(e.span_s, 2) + " s, gyro std " + FormatFixed(e.gyro_std_radps, 3) +
                             " rad/s, accel std " + FormatFixed(e.accel_std_mps2, 3) + " m/s^2";
  std::string cause;
  if (e.frames == 0) {
    cause = "no camera frame lies inside the IMU's time span";
  } else if (e.frames < window_frames) {
    cause = "too few camera frames (" + std::to_string(e.frames) +
            " inside the IMU's time span, the window needs " + std::to_string(window_frames) + ")";
  } else if (e.max_features <= options.vins.min_correspondences) {
    cause = "too few features (at most " + std::to_string(e.max_features) +
            " per frame, the initializer needs more than " +
            std::to_string(options.vins.min_correspondences) + ")";
  } else if (e.max_displacement_px < kStationaryDisplacement_px) {
    cause = "the platform did not move: stationary for the whole recording (" + motion +
            "); a visual-inertial start needs motion";
  } else if (last_attempt.rfind("sfm: no reference frame", 0) == 0) {
    cause = "not enough motion or parallax (" + motion + "; the initializer needs " +
            FormatFixed(options.vins.min_parallax_px, 1) + " px of mean parallax)";
  } else if (last_attempt.find("alignment") != std::string::npos ||
             last_attempt.find("gravity") != std::string::npos ||
             last_attempt.find("gyro bias") != std::string::npos) {
    cause = "IMU excitation too low or inconsistent with the camera for visual-inertial alignment (" +
            motion + ")";
  } else if (last_attempt.rfind("sfm:", 0) == 0) {
    cause = "structure from motion failed (" + motion + ")";
  } else {
    cause = "the initializer failed (" + motion + ")";
  }
  return last_attempt.empty() ? cause : cause + "; last attempt: " + last_attempt;
}

}  // namespace vigil::estimator
