#include "estimator/init/vins_initializer.h"

#include <algorithm>
#include <string>

#include "core/format.h"
#include "core/so3.h"
#include "estimator/init/visual_inertial_alignment.h"

namespace vigil::estimator {
namespace {

constexpr int kGyroBiasIterations = 3;

}  // namespace

VinsInitializer::VinsInitializer(const VinsInitOptions& options, const CameraModel& camera,
                                 double gravity_mps2, int window_frames)
    : options_(options),
      R_BC_(camera.R_BC()),
      p_BC_(camera.p_BC()),
      fx_(camera.fx),
      gravity_mps2_(gravity_mps2),
      window_frames_(static_cast<std::size_t>(std::max(window_frames, 2))) {}

WindowSfmOptions VinsInitializer::SfmOptions() const {
  WindowSfmOptions sfm;
  sfm.min_correspondences = options_.min_correspondences;
  sfm.min_parallax = options_.min_parallax_px / fx_;
  sfm.relative_pose.ransac_iterations = options_.ransac_iterations;
  sfm.relative_pose.inlier_threshold = options_.ransac_threshold_px / fx_;
  sfm.relative_pose.min_inliers = options_.min_ransac_inliers;
  sfm.relative_pose.seed = options_.ransac_seed;
  sfm.min_pnp_points = options_.min_pnp_points;
  sfm.bundle_adjustment_iterations = options_.bundle_adjustment_iterations;
  sfm.max_rms_reprojection = options_.max_reprojection_px / fx_;
  return sfm;
}

bool VinsInitializer::GyroAgreesWithVision(const std::vector<AlignmentFrame>& frames,
                                           const Eigen::Vector3d& b_g, InitResult* result) const {
  if (options_.max_gyro_residual_deg <= 0.0) return true;
  const std::vector<double> residuals_rad = GyroRotationResiduals(frames, b_g);
  const auto worst = std::max_element(residuals_rad.begin(), residuals_rad.end());
  if (worst == residuals_rad.end()) return true;
  const double worst_deg = *worst * 180.0 / M_PI;
  if (worst_deg <= options_.max_gyro_residual_deg) return true;
  const std::size_t k = static_cast<std::size_t>(worst - residuals_rad.begin()) + 1;
  result->failure_reason = "the gyroscope and the vision disagree by " + FormatFixed(worst_deg, 2) +
                           " deg between window frames " + std::to_string(k - 1) + " and " +
                           std::to_string(k) + " after the bias solve (vins.max_gyro_residual_deg " +
                           FormatDouble(options_.max_gyro_residual_deg) + ")";
  return false;
}

bool VinsInitializer::TryInitialize(const std::vector<InitFrame>& window, InitResult* result) {
  *result = InitResult{};
  const std::size_t n = window.size();
  if (n < window_frames_) {
    result->failure_reason =
        "window not full (" + std::to_string(n) + " of " + std::to_string(window_frames_) + " frames)";
    return false;
  }
  for (std::size_t k = 1; k < n; ++k) {
    if (!window[k].imu_from_prev) {
      result->failure_reason = "window frame " + std::to_string(k) + " has no IMU from its predecessor";
      return false;
    }
  }

  // 1. Vision only, up to scale, in the reference camera frame L.
  std::vector<FeatureMap> features(n);
  for (std::size_t k = 0; k < n; ++k) features[k] = window[k].features_n;
  WindowSfmResult sfm;
  if (!WindowSfm(features, SfmOptions(), &sfm)) {
    result->failure_reason = "sfm: " + sfm.failure_reason;
    return false;
  }

  // 2. Gyro bias from SfM rotations vs preintegrated rotations, then re-integrate with it.
  std::vector<Preintegration> imu;
  imu.reserve(n - 1);
  for (std::size_t k = 1; k < n; ++k) imu.push_back(*window[k].imu_from_prev);
  std::vector<AlignmentFrame> frames(n);
  for (std::size_t k = 0; k < n; ++k) {
    frames[k].R_LB = sfm.q_LC[k].toRotationMatrix() * R_BC_.transpose();
    frames[k].p_LC = sfm.p_LC[k];
    frames[k].imu_from_prev = k > 0 ? &imu[k - 1] : nullptr;
  }
  Eigen::Vector3d b_g;
  if (!SolveGyroBias(frames, imu.front().linearized_b_g(), kGyroBiasIterations, &b_g)) {
    result->failure_reason = "gyro bias least squares is singular";
    return false;
  }
  if (!GyroAgreesWithVision(frames, b_g, result)) return false;
  const Eigen::Vector3d b_a = imu.front().linearized_b_a();
  for (auto& pre : imu) pre.Repropagate(b_a, b_g);

  // 3. Velocities, gravity and scale; gravity refined on the sphere.
  Alignment alignment;
  std::string why;
  if (!LinearAlignment(frames, p_BC_, gravity_mps2_, options_.max_gravity_error_mps2, &alignment, &why) ||
      !RefineGravity(frames, p_BC_, gravity_mps2_, options_.gravity_refinement_iterations, &alignment,
                     &why)) {
    result->failure_reason = why;
    return false;
  }

  // 4. World frame: gravity along -z, yaw of the first body frame zero, first body position at the origin.
  Eigen::Matrix3d R_WL =
      Eigen::Quaterniond::FromTwoVectors(alignment.g_L, -Eigen::Vector3d::UnitZ()).toRotationMatrix();
  R_WL = RotZ(-YawOf(R_WL * frames[0].R_LB)) * R_WL;
  const double s = alignment.scale;
  const Eigen::Vector3d p_LB0 = s * frames[0].p_LC - frames[0].R_LB * p_BC_;
  result->states.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    NavState& x = result->states[k];
    x.t_ns = window[k].t_ns;
    x.q_WB = Eigen::Quaterniond(R_WL * frames[k].R_LB).normalized();
    x.p_W = R_WL * (s * frames[k].p_LC - frames[k].R_LB * p_BC_ - p_LB0);
    x.v_W = R_WL * alignment.v_L[k];
    x.b_g = b_g;
    x.b_a = b_a;
    if (!x.p_W.allFinite() || !x.v_W.allFinite() || !x.q_WB.coeffs().allFinite()) {
      result->states.clear();
      result->failure_reason = "non-finite state after alignment";
      return false;
    }
  }
  for (const auto& [id, p_L] : sfm.points_L) result->landmarks_W[id] = R_WL * (s * p_L - p_LB0);
  return true;
}

}  // namespace vigil::estimator
