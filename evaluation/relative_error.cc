#include "evaluation/relative_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/so3.h"

namespace vigil::evaluation {

std::vector<double> DistanceFromStart(const std::vector<Eigen::Vector3d>& p) {
  std::vector<double> d(p.size(), 0.0);
  for (std::size_t k = 1; k < p.size(); ++k) d[k] = d[k - 1] + (p[k] - p[k - 1]).norm();
  return d;
}

std::vector<std::pair<std::size_t, std::size_t>> SubTrajectoryPairs(const std::vector<double>& distances,
                                                                    double distance_m,
                                                                    double max_difference_m) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < distances.size(); ++i) {
    const double target = distances[i] + distance_m;
    const auto begin = distances.begin() + static_cast<std::ptrdiff_t>(i);
    // |distances[j] - target| decreases up to the first j with distances[j] >= target and increases after it:
    // the best end is that j or the first index of the value just below it.
    const auto above = std::lower_bound(begin, distances.end(), target);
    std::size_t best = distances.size();
    double best_error = max_difference_m;
    if (above != begin) {
      const auto below = std::lower_bound(begin, above, *(above - 1));
      const double e = std::abs(*below - target);
      if (e < best_error) best = static_cast<std::size_t>(below - distances.begin()), best_error = e;
    }
    if (above != distances.end()) {
      const double e = std::abs(*above - target);
      if (e < best_error) best = static_cast<std::size_t>(above - distances.begin()), best_error = e;
    }
    if (best != distances.size()) pairs.emplace_back(i, best);
  }
  return pairs;
}

RelativeErrors ComputeRelativeErrors(const std::vector<Eigen::Isometry3d>& T_W_est,
                                     const std::vector<Eigen::Isometry3d>& T_W_gt, double distance_m,
                                     double scale, double max_difference_m) {
  if (T_W_est.size() != T_W_gt.size())
    throw std::invalid_argument("ComputeRelativeErrors: estimate and ground truth differ in length");
  RelativeErrors out;
  out.distance_m = distance_m;
  if (max_difference_m < 0.0) max_difference_m = 0.2 * distance_m;
  std::vector<Eigen::Vector3d> p_gt(T_W_gt.size());
  for (std::size_t k = 0; k < T_W_gt.size(); ++k) p_gt[k] = T_W_gt[k].translation();
  const auto pairs = SubTrajectoryPairs(DistanceFromStart(p_gt), distance_m, max_difference_m);
  if (pairs.size() < 2) return out;
  for (const auto& [i, j] : pairs) {
    Eigen::Isometry3d T_c = T_W_est[i].inverse() * T_W_est[j];
    T_c.translation() *= scale;
    const Eigen::Isometry3d T_m = T_W_gt[i].inverse() * T_W_gt[j];
    const Eigen::Isometry3d E = T_m.inverse() * T_c;
    const Eigen::Matrix3d R_j = T_W_est[j].linear();
    const Eigen::Matrix3d E_R_W = R_j * E.linear() * R_j.transpose();
    const double trans = E.translation().norm();  // |R_j E_t| = |E_t|
    out.trans_m.push_back(trans);
    out.trans_perc.push_back(100.0 * trans / distance_m);
    out.yaw_deg.push_back(std::abs(YawOf(E_R_W)) * 180.0 / M_PI);
    const double cos_angle = std::clamp((E.linear().trace() - 1.0) / 2.0, -1.0, 1.0);
    out.rot_deg.push_back(std::acos(cos_angle) * 180.0 / M_PI);
  }
  return out;
}

}  // namespace vigil::evaluation
