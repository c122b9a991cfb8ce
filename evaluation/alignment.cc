#include "evaluation/alignment.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/SVD>

#include "core/so3.h"

namespace vigil::evaluation {
namespace {

Eigen::Vector3d Mean(const std::vector<Eigen::Vector3d>& p) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& x : p) sum += x;
  return sum / static_cast<double>(p.size());
}

}  // namespace

SimilarityTransform AlignPositions(const std::vector<Eigen::Vector3d>& p_est,
                                   const std::vector<Eigen::Vector3d>& p_gt, Alignment align) {
  if (p_est.size() != p_gt.size() || p_est.empty())
    throw std::invalid_argument(
        "AlignPositions: needs the same, non-zero number of estimate and ground-truth "
        "positions");
  SimilarityTransform T;
  if (align == Alignment::kNone) return T;
  const Eigen::Vector3d mu_est = Mean(p_est), mu_gt = Mean(p_gt);
  if (p_est.size() == 1) {
    T.t = mu_gt - mu_est;
    return T;
  }
  const double n = static_cast<double>(p_est.size());
  // C = 1/n sum (m - mu_m)(d - mu_d)^T; sigma2 = 1/n sum |d - mu_d|^2.
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  double sigma2 = 0.0;
  for (std::size_t k = 0; k < p_est.size(); ++k) {
    const Eigen::Vector3d d = p_est[k] - mu_est, m = p_gt[k] - mu_gt;
    C += m * d.transpose();
    sigma2 += d.squaredNorm();
  }
  C /= n;
  sigma2 /= n;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(C, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) S(2, 2) = -1.0;
  if (align == Alignment::kPosYaw) {
    const Eigen::Matrix3d C_yaw = n * C.transpose();  // sum (d - mu_d)(m - mu_m)^T
    const double yaw = M_PI / 2.0 - std::atan2(C_yaw(0, 0) + C_yaw(1, 1), C_yaw(0, 1) - C_yaw(1, 0));
    T.R = RotZ(yaw);
  } else {
    T.R = svd.matrixU() * S * svd.matrixV().transpose();
  }
  if (align == Alignment::kSim3 && sigma2 > 0.0)
    T.scale = (svd.singularValues().asDiagonal() * S).trace() / sigma2;
  T.t = mu_gt - T.scale * (T.R * mu_est);
  return T;
}

}  // namespace vigil::evaluation
