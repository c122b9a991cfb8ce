#include "estimator/init/relative_pose.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <ceres/ceres.h>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "core/random.h"
#include "core/so3.h"
#include "estimator/init/triangulation.h"

namespace vigil::estimator {
namespace {

// Similarity T (centroid to the origin, mean distance sqrt(2)) applied to homogeneous points.
Eigen::Matrix3d ConditioningTransform(const std::vector<Eigen::Vector2d>& x) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : x) mean += p;
  mean /= static_cast<double>(x.size());
  double dist = 0.0;
  for (const auto& p : x) dist += (p - mean).norm();
  dist /= static_cast<double>(x.size());
  const double s = dist > 1e-12 ? std::sqrt(2.0) / dist : 1.0;
  Eigen::Matrix3d T;
  T << s, 0, -s * mean.x(), 0, s, -s * mean.y(), 0, 0, 1;
  return T;
}

Eigen::Matrix3d ProjectToEssential(const Eigen::Matrix3d& F) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d s = svd.singularValues();
  const double mean = 0.5 * (s[0] + s[1]);
  return svd.matrixU() * Eigen::Vector3d(mean, mean, 0.0).asDiagonal() * svd.matrixV().transpose();
}

// Sampson distance of one correspondence to E = [t]x R, for the nonlinear refinement (q in Eigen order x, y,
// z, w).
struct SampsonResidual {
  SampsonResidual(const Eigen::Vector2d& x1, const Eigen::Vector2d& x2) : x1_(x1), x2_(x2) {}
  template <class T>
  bool operator()(const T* q, const T* t, T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q_21(q);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_21(t);
    const Eigen::Matrix<T, 3, 1> a = x1_.homogeneous().cast<T>(), b = x2_.homogeneous().cast<T>();
    const Eigen::Matrix<T, 3, 1> Ea = t_21.cross(q_21 * a);                 // E a
    const Eigen::Matrix<T, 3, 1> Etb = q_21.conjugate() * (b.cross(t_21));  // E^T b = R^T [t]x^T b
    const T den = Ea.x() * Ea.x() + Ea.y() * Ea.y() + Etb.x() * Etb.x() + Etb.y() * Etb.y();
    residual[0] = b.dot(Ea) / ceres::sqrt(den);
    return true;
  }
  Eigen::Vector2d x1_, x2_;
};

// Minimizes the Sampson distances of the inliers over (R_21, unit t_21).
void RefineOnInliers(const std::vector<Eigen::Vector2d>& x1, const std::vector<Eigen::Vector2d>& x2,
                     const std::vector<bool>& inliers, Eigen::Matrix3d* R_21, Eigen::Vector3d* t_21) {
  Eigen::Quaterniond q(*R_21);
  Eigen::Vector3d t = t_21->normalized();
  ceres::Problem problem;
  problem.AddParameterBlock(q.coeffs().data(), 4, new ceres::EigenQuaternionManifold);
  problem.AddParameterBlock(t.data(), 3, new ceres::SphereManifold<3>);
  for (std::size_t i = 0; i < x1.size(); ++i) {
    if (!inliers[i]) continue;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<SampsonResidual, 1, 4, 3>(new SampsonResidual(x1[i], x2[i])), nullptr,
        q.coeffs().data(), t.data());
  }
  ceres::Solver::Options options;
  options.max_num_iterations = 20;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (summary.termination_type == ceres::FAILURE || !q.coeffs().allFinite() || !t.allFinite()) return;
  *R_21 = q.normalized().toRotationMatrix();
  *t_21 = t.normalized();
}

}  // namespace

bool EssentialEightPoint(const std::vector<Eigen::Vector2d>& x1, const std::vector<Eigen::Vector2d>& x2,
                         Eigen::Matrix3d* E) {
  const std::size_t n = x1.size();
  if (n < 8 || x2.size() != n) return false;
  const Eigen::Matrix3d T1 = ConditioningTransform(x1), T2 = ConditioningTransform(x2);
  Eigen::MatrixXd A(n, 9);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d a = T1 * x1[i].homogeneous(), b = T2 * x2[i].homogeneous();
    // b^T F a = sum_rc b_r F_rc a_c, F stored row-major in the null vector.
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) A(static_cast<Eigen::Index>(i), 3 * r + c) = b[r] * a[c];
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::VectorXd f = svd.matrixV().col(8);
  Eigen::Matrix3d F;
  F << f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8];
  // Undo the conditioning (x2'^T F x1' = x2^T T2^T F T1 x1), then enforce the essential structure.
  Eigen::Matrix3d E_raw = T2.transpose() * F * T1;
  E_raw /= E_raw.norm();
  *E = ProjectToEssential(E_raw);
  return true;
}

double SampsonDistance(const Eigen::Matrix3d& E, const Eigen::Vector2d& x1, const Eigen::Vector2d& x2) {
  const Eigen::Vector3d a = x1.homogeneous(), b = x2.homogeneous();
  const Eigen::Vector3d Ea = E * a, Etb = E.transpose() * b;
  const double num = b.dot(Ea);
  const double den = Ea.head<2>().squaredNorm() + Etb.head<2>().squaredNorm();
  return den > 0.0 ? std::abs(num) / std::sqrt(den) : std::numeric_limits<double>::infinity();
}

int DecomposeEssential(const Eigen::Matrix3d& E, const std::vector<Eigen::Vector2d>& x1,
                       const std::vector<Eigen::Vector2d>& x2, const std::vector<bool>& mask,
                       Eigen::Matrix3d* R_21, Eigen::Vector3d* t_21) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(E, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU(), V = svd.matrixV();
  if (U.determinant() < 0) U = -U;
  if (V.determinant() < 0) V = -V;
  Eigen::Matrix3d W;
  W << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Eigen::Matrix3d Ra = U * W * V.transpose(), Rb = U * W.transpose() * V.transpose();
  const Eigen::Vector3d u3 = U.col(2);
  const Eigen::Matrix3d Rs[4] = {Ra, Ra, Rb, Rb};
  const Eigen::Vector3d ts[4] = {u3, -u3, u3, -u3};
  int best = -1;
  Eigen::Matrix<double, 3, 4> P1;
  P1.setZero();
  P1.leftCols<3>().setIdentity();
  for (int k = 0; k < 4; ++k) {
    Eigen::Matrix<double, 3, 4> P2;
    P2 << Rs[k], ts[k];
    int in_front = 0;
    for (std::size_t i = 0; i < x1.size(); ++i) {
      if (!mask.empty() && !mask[i]) continue;
      Eigen::Vector3d p1;
      if (!TriangulateDlt({P1, P2}, {x1[i], x2[i]}, &p1)) continue;
      const Eigen::Vector3d p2 = Rs[k] * p1 + ts[k];
      if (p1.z() > 0.0 && p2.z() > 0.0) ++in_front;
    }
    if (in_front > best) {
      best = in_front;
      *R_21 = Rs[k];
      *t_21 = ts[k];
    }
  }
  return best;
}

bool EstimateRelativePose(const std::vector<Eigen::Vector2d>& x1, const std::vector<Eigen::Vector2d>& x2,
                          const RelativePoseOptions& options, RelativePose* pose) {
  const std::size_t n = x1.size();
  if (n < 8 || x2.size() != n) return false;
  Rng rng(options.seed, "init_ransac");
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  std::vector<bool> best_inliers;
  int best_count = -1;
  std::vector<Eigen::Vector2d> s1(8), s2(8);
  for (int it = 0; it < options.ransac_iterations; ++it) {
    // Partial Fisher-Yates: the first 8 entries of idx are a uniform sample without replacement.
    for (std::size_t k = 0; k < 8; ++k) {
      const std::size_t j = k + static_cast<std::size_t>(rng.UniformIndex(n - k));
      std::swap(idx[k], idx[j]);
      s1[k] = x1[idx[k]];
      s2[k] = x2[idx[k]];
    }
    Eigen::Matrix3d E;
    if (!EssentialEightPoint(s1, s2, &E)) continue;
    std::vector<bool> inliers(n);
    int count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      inliers[i] = SampsonDistance(E, x1[i], x2[i]) < options.inlier_threshold;
      count += inliers[i];
    }
    if (count > best_count) {
      best_count = count;
      best_inliers = std::move(inliers);
      if (count == static_cast<int>(n)) break;
    }
  }
  if (best_count < std::max(options.min_inliers, 8)) return false;
  // Refit on all inliers, then recount.
  std::vector<Eigen::Vector2d> in1, in2;
  for (std::size_t i = 0; i < n; ++i)
    if (best_inliers[i]) {
      in1.push_back(x1[i]);
      in2.push_back(x2[i]);
    }
  Eigen::Matrix3d E;
  if (!EssentialEightPoint(in1, in2, &E)) return false;
  pose->inliers.assign(n, false);
  pose->num_inliers = 0;
  for (std::size_t i = 0; i < n; ++i) {
    pose->inliers[i] = SampsonDistance(E, x1[i], x2[i]) < options.inlier_threshold;
    pose->num_inliers += pose->inliers[i];
  }
  if (pose->num_inliers < options.min_inliers) return false;
  if (DecomposeEssential(E, x1, x2, pose->inliers, &pose->R_21, &pose->t_21) < options.min_inliers)
    return false;
  // The linear estimate is biased by noise; refine (R, t) on the inliers and recount with the refined E.
  RefineOnInliers(x1, x2, pose->inliers, &pose->R_21, &pose->t_21);
  const Eigen::Matrix3d E_refined = Skew(pose->t_21) * pose->R_21;
  pose->num_inliers = 0;
  for (std::size_t i = 0; i < n; ++i) {
    pose->inliers[i] = SampsonDistance(E_refined, x1[i], x2[i]) < options.inlier_threshold;
    pose->num_inliers += pose->inliers[i];
  }
  return pose->num_inliers >= options.min_inliers;
}

}  // namespace vigil::estimator
