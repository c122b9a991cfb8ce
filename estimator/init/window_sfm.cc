#include "estimator/init/window_sfm.h"

#include <cmath>
#include <memory>
#include <string>

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include "core/format.h"
#include "estimator/init/triangulation.h"

namespace vigil::estimator {
namespace {

// Reprojection on the normalized plane of camera C of a point in L; pose as (q_CL, p_CL).
struct NormalizedReprojection {
  explicit NormalizedReprojection(const Eigen::Vector2d& obs) : obs_(obs) {}
  template <class T>
  bool operator()(const T* q, const T* p, const T* point, T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q_CL(q);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> p_CL(p), p_L(point);
    const Eigen::Matrix<T, 3, 1> p_C = q_CL * p_L + p_CL;
    residual[0] = p_C.x() / p_C.z() - T(obs_.x());
    residual[1] = p_C.y() / p_C.z() - T(obs_.y());
    return true;
  }
  Eigen::Vector2d obs_;
};

// Window poses as T_CL during the reconstruction.
struct Poses {
  std::vector<bool> known;
  std::vector<Eigen::Matrix3d> R_CL;
  std::vector<Eigen::Vector3d> p_CL;
  Projection P(std::size_t i) const {
    Projection P;
    P << R_CL[i], p_CL[i];
    return P;
  }
};

// Triangulates every feature not yet in `points` that is seen by at least two posed frames; keeps it when it
// lies in front of every observing camera.
void TriangulateNew(const std::vector<FeatureMap>& frames, const Poses& poses,
                    std::map<int, Eigen::Vector3d>* points) {
  std::map<int, std::pair<std::vector<Projection>, std::vector<Eigen::Vector2d>>> tracks;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (!poses.known[i]) continue;
    for (const auto& [id, x] : frames[i]) {
      if (points->count(id)) continue;
      tracks[id].first.push_back(poses.P(i));
      tracks[id].second.push_back(x);
    }
  }
  for (const auto& [id, track] : tracks) {
    if (track.first.size() < 2) continue;
    Eigen::Vector3d p_L;
    if (!TriangulateDlt(track.first, track.second, &p_L)) continue;
    bool in_front = true;
    for (const auto& P : track.first) in_front = in_front && DepthIn(P, p_L) > 0.0;
    if (in_front) (*points)[id] = p_L;
  }
}

bool LocalizeByPnp(const std::vector<FeatureMap>& frames, std::size_t i, std::size_t guess,
                   const std::map<int, Eigen::Vector3d>& points, const WindowSfmOptions& options,
                   Poses* poses) {
  std::vector<Eigen::Vector3d> pts;
  std::vector<Eigen::Vector2d> obs;
  for (const auto& [id, x] : frames[i]) {
    const auto it = points.find(id);
    if (it == points.end()) continue;
    pts.push_back(it->second);
    obs.push_back(x);
  }
  if (static_cast<int>(pts.size()) < options.min_pnp_points) return false;
  Eigen::Matrix3d R = poses->R_CL[guess];
  Eigen::Vector3d p = poses->p_CL[guess];
  if (!SolvePnp(pts, obs, options.pnp, &R, &p)) return false;
  poses->R_CL[i] = R;
  poses->p_CL[i] = p;
  poses->known[i] = true;
  return true;
}

}  // namespace

double MeanParallax(const FeatureMap& a, const FeatureMap& b, int* shared) {
  double sum = 0.0;
  int n = 0;
  for (const auto& [id, xa] : a) {
    const auto it = b.find(id);
    if (it == b.end()) continue;
    sum += (it->second - xa).norm();
    ++n;
  }
  if (shared) *shared = n;
  return n > 0 ? sum / n : 0.0;
}

bool WindowSfm(const std::vector<FeatureMap>& frames, const WindowSfmOptions& options,
               WindowSfmResult* result) {
  *result = WindowSfmResult{};
  const std::size_t n = frames.size();
  if (n < 2) {
    result->failure_reason = "fewer than two frames";
    return false;
  }
  const std::size_t newest = n - 1;

  // 1. Reference frame L and its relative pose to the newest frame.
  RelativePose rel;
  int best_shared = 0;
  double best_parallax = 0.0;
  for (std::size_t i = 0; i < newest && result->reference_frame < 0; ++i) {
    int shared = 0;
    const double parallax = MeanParallax(frames[i], frames[newest], &shared);
    best_shared = std::max(best_shared, shared);
    best_parallax = std::max(best_parallax, parallax);
    if (shared <= options.min_correspondences || parallax <= options.min_parallax) continue;
    std::vector<Eigen::Vector2d> x1, x2;
    for (const auto& [id, x] : frames[i]) {
      const auto it = frames[newest].find(id);
      if (it == frames[newest].end()) continue;
      x1.push_back(x);
      x2.push_back(it->second);
    }
    if (EstimateRelativePose(x1, x2, options.relative_pose, &rel))
      result->reference_frame = static_cast<int>(i);
  }
  if (result->reference_frame < 0) {
    result->failure_reason = "no reference frame (best: " + std::to_string(best_shared) +
                             " shared features, mean parallax " + FormatFixed(best_parallax, 4) +
                             " normalized)";
    return false;
  }
  const std::size_t l = static_cast<std::size_t>(result->reference_frame);

  // 2. Poses of L and the newest frame, points they share.
  Poses poses{std::vector<bool>(n, false), std::vector<Eigen::Matrix3d>(n, Eigen::Matrix3d::Identity()),
              std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero())};
  poses.known[l] = true;
  poses.known[newest] = true;
  poses.R_CL[newest] = rel.R_21;
  poses.p_CL[newest] = rel.t_21;
  std::map<int, Eigen::Vector3d>& points = result->points_L;
  TriangulateNew(frames, poses, &points);

  // 3. Frames after L (guess: the previous frame), then before L (guess: the next one).
  for (std::size_t i = l + 1; i < newest; ++i) {
    if (!LocalizeByPnp(frames, i, i - 1, points, options, &poses)) {
      result->failure_reason = "PnP failed for window frame " + std::to_string(i);
      return false;
    }
    TriangulateNew(frames, poses, &points);
  }
  for (std::size_t k = l; k-- > 0;) {
    if (!LocalizeByPnp(frames, k, k + 1, points, options, &poses)) {
      result->failure_reason = "PnP failed for window frame " + std::to_string(k);
      return false;
    }
    TriangulateNew(frames, poses, &points);
  }

  // 4. Bundle adjustment over every pose and point.
  std::vector<Eigen::Quaterniond> q_CL(n);
  for (std::size_t i = 0; i < n; ++i) q_CL[i] = Eigen::Quaterniond(poses.R_CL[i]).normalized();
  ceres::Problem problem;
  for (std::size_t i = 0; i < n; ++i) {
    problem.AddParameterBlock(q_CL[i].coeffs().data(), 4, new ceres::EigenQuaternionManifold);
    problem.AddParameterBlock(poses.p_CL[i].data(), 3);
  }
  int residuals = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& [id, x] : frames[i]) {
      auto it = points.find(id);
      if (it == points.end()) continue;
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<NormalizedReprojection, 2, 4, 3, 3>(new NormalizedReprojection(x)),
          nullptr, q_CL[i].coeffs().data(), poses.p_CL[i].data(), it->second.data());
      ++residuals;
    }
  }
  problem.SetParameterBlockConstant(q_CL[l].coeffs().data());
  problem.SetParameterBlockConstant(poses.p_CL[l].data());
  problem.SetParameterBlockConstant(poses.p_CL[newest].data());
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_SCHUR;
  solver.max_num_iterations = options.bundle_adjustment_iterations;
  solver.num_threads = 1;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (summary.termination_type == ceres::FAILURE || !std::isfinite(summary.final_cost)) {
    result->failure_reason = "bundle adjustment failed: " + summary.message;
    return false;
  }
  result->rms_reprojection = residuals > 0 ? std::sqrt(2.0 * summary.final_cost / residuals) : 0.0;
  if (result->rms_reprojection > options.max_rms_reprojection) {
    result->failure_reason = "bundle adjustment RMS reprojection " +
                             FormatFixed(result->rms_reprojection, 5) + " (normalized) is too large";
    return false;
  }

  // 5. Invert to camera poses in L.
  result->q_LC.resize(n);
  result->p_LC.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    result->q_LC[i] = q_CL[i].normalized().conjugate();
    result->p_LC[i] = -(result->q_LC[i] * poses.p_CL[i]);
  }
  return true;
}

}  // namespace vigil::estimator
