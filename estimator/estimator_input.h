// What the estimator consumes and what it returns.
//
// The estimator knows nothing of the simulator: IMU samples, feature observations per camera frame (track id
// + pixel), the camera model and the IMU noise densities are all it needs, so real feature tracks and IMU
// logs fill the same struct. Ground truth enters only for `estimator.init: groundtruth`.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/types.h"

namespace vigil::estimator {

// Continuous-time IMU noise densities (the datasheet values), discretized by the preintegration.
struct ImuNoiseDensities {
  double gyro_noise_density = 0.015;     // [rad/s/sqrt(Hz)]
  double accel_noise_density = 0.019;    // [m/s^2/sqrt(Hz)]
  double gyro_bias_random_walk = 1e-5;   // [rad/s^2/sqrt(Hz)]
  double accel_bias_random_walk = 1e-4;  // [m/s^3/sqrt(Hz)]
};

// A frame's observations as the estimator takes them: track id -> normalized image point.
inline std::map<int, Eigen::Vector2d> NormalizedFeatures(const CameraFrame& frame,
                                                         const CameraModel& camera) {
  std::map<int, Eigen::Vector2d> features_n;
  for (const FeatureObservation& obs : frame.features) features_n[obs.id] = camera.Normalize(obs.uv_px);
  return features_n;
}

struct EstimatorInput {
  ImuStream imu;  // time-ordered, the stream the estimator integrates (cleaned or raw)
  std::vector<CameraFrame>
      frames;  // time-ordered camera frames with their observations (empty frames allowed)
  CameraModel camera;
  ImuNoiseDensities imu_noise;  // the sensor's own densities (estimator.imu_noise says what is used)
  double gravity_mps2 = 9.81;   // g_W = (0, 0, -g)
  std::vector<NavState>
      groundtruth;    // only read by init = groundtruth (at any rate covering the frame times)
  uint64_t seed = 0;  // run seed: the optional ground-truth init perturbation derives from it
  // Empty, or one per imu sample: 1 where a detector flagged the sample (read by
  // estimator.mitigation.inflate).
  std::vector<uint8_t> imu_flagged;
};

// What in-estimator mitigation and the timestamp check did over a run (mitigation_options.h).
struct MitigationStats {
  int repeated_timestamps = 0;  // IMU samples dropped because their timestamp did not increase
  int inflated_samples = 0;     // flagged samples with inflated noise
  int clipped_samples = 0;      // samples at the full-scale range with inflated noise
  int gate_tests = 0;           // IMU factor chi-square tests
  int gated_factors = 0;        // failing tests (factor inflated)
  int gated_resolves = 0;       // solves repeated after gating
};

// What the IMU noise measured at rest found and what the estimator used (rest_noise.h; metrics.json
// "estimator.imu_noise_at_rest").
struct RestNoise {
  double start_s = 0.0;  // start of the rest measured, from the first camera frame
  double rest_s = 0.0;   // its length (0: no rest of at least min_rest_s)
  double tau_s = 0.0;    // averaging time of the Allan deviation (the camera period)
  int differences = 0;   // cluster-mean differences pooled per sensor (3 per cluster pair)
  // Measured white-noise densities; empty without a rest or when it held fewer than 3 x 8 differences.
  std::optional<double> gyro_noise_density;   // [rad/s/sqrt(Hz)]
  std::optional<double> accel_noise_density;  // [m/s^2/sqrt(Hz)]
  bool gyro_applied = false;                  // the white-noise density replaced by the measured one
  bool accel_applied = false;
  bool gyro_bias_walk_applied = false;  // the bias random walk scaled by measured / model white noise
  bool accel_bias_walk_applied = false;
};

// Wall-clock cost of the estimator's stages, summed over the run.
struct EstimatorTiming {
  double optimize_s = 0.0;
  double marginalize_s = 0.0;
  double initialize_s = 0.0;
  double covariance_s = 0.0;  // the newest pose's covariance (pose_covariance.h)
  int optimizations = 0;
  int solver_iterations = 0;  // Ceres iterations (successful and unsuccessful steps) over all solves
  int marginalizations = 0;
};

struct EstimatorResult {
  bool ok = true;  // false: diverged or failed; `failure_reason` says why
  std::string failure_reason;
  // One state per solved camera frame after initialization, the newest window state (every frame unless
  // EstimatorOptions::max_frame_rate_hz); with predict_between_solves also one per frame left out, the IMU's
  // prediction from the last solved one. Never NaN/Inf. Trajectory rows are the same poses.
  std::vector<NavState> states;
  Trajectory trajectory;
  // One per trajectory row when options.pose_covariance (else empty): the pose's covariance in its tangent
  // [delta p_W, delta theta_B] (pose_covariance.h); rows whose covariance could not be computed, and the
  // predicted frames' rows, are NaN.
  std::vector<Eigen::Matrix<double, 6, 6>> pose_covariances;
  double initialized_at_s =
      std::numeric_limits<double>::quiet_NaN();  // first successful init, s after the first IMU sample
  int resets = 0;  // failure-detection resets (each followed by re-initialization)
  int stops = 0;   // failure-detection stops (1 when a failure ended the run, else 0)
  std::map<std::string, int> failure_checks;  // resets + stops by the check that fired (Estimator)
  int frames = 0;                             // camera frames processed (solved or left out)
  int solved_frames = 0;  // camera frames the window was solved at (EstimatorOptions::max_frame_rate_hz)
  int keyframes = 0;      // frames kept as keyframes (oldest marginalized)
  int marginalization_failures = 0;  // failed marginalizations: the prior was dropped each time
  EstimatorTiming timing;
  MitigationStats mitigation;
  RestNoise rest_noise;
};

}  // namespace vigil::estimator
