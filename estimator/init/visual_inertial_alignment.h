// Visual-inertial alignment of an up-to-scale SfM window with IMU preintegration (the VINS recipe).
//
// Inputs per window frame k: the body orientation R_LB_k and the camera position p_LC_k of the SfM (frame L,
// arbitrary scale), and the preintegration from frame k-1 to k (k >= 1). Extrinsics: p_B = R_BC p_C + p_BC.
// The metric body position is p_LB_k = s p_LC_k - R_LB_k p_BC for the unknown scale s.
//
//   1. SolveGyroBias: b_g minimizing sum |Log(dq_k(b_g)^-1 R_LB_{k-1}^T R_LB_k)|^2 (Gauss-Newton with the
//      preintegration's d theta / d b_g block).
//   2. LinearAlignment: with the bias-corrected deltas (alpha, beta) of each pair (i, j = i + 1, dt = T),
//        s (p_LC_j - p_LC_i) - v_i T - 1/2 g_L T^2 = R_LB_i alpha + (R_LB_j - R_LB_i) p_BC
//        v_j - v_i - g_L T                         = R_LB_i beta
//      solved by least squares for every velocity v_k (in L), gravity g_L and s.
//   3. RefineGravity: the same equations with |g_L| fixed to the nominal g, g_L = g * n + B w where B spans
//   the
//      tangent plane of the current direction n; each iteration solves for (v, w, s) and re-normalizes.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "estimator/preintegration.h"

namespace vigil::estimator {

struct AlignmentFrame {
  Eigen::Matrix3d R_LB = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_LC = Eigen::Vector3d::Zero();  // up to scale
  const Preintegration* imu_from_prev = nullptr;   // null for the first frame only
};

struct Alignment {
  std::vector<Eigen::Vector3d> v_L;  // per frame, metric
  Eigen::Vector3d g_L = Eigen::Vector3d::Zero();
  double scale = 0.0;
};

// Gyro bias estimate (absolute, starting from `b_g_start`). False for fewer than two frames or a singular
// system.
bool SolveGyroBias(const std::vector<AlignmentFrame>& frames, const Eigen::Vector3d& b_g_start,
                   int iterations, Eigen::Vector3d* b_g);

// Per pair k = 1..n-1 (index k-1), the angle [rad] between the vision's relative rotation and the
// preintegrated one corrected with b_g: what the bias cannot explain. Empty without IMU between every pair.
std::vector<double> GyroRotationResiduals(const std::vector<AlignmentFrame>& frames,
                                          const Eigen::Vector3d& b_g);

// Free-gravity linear alignment. False (with `why`) for a singular system, s <= 0, or | |g_L| - gravity | >
// max_gravity_error.
bool LinearAlignment(const std::vector<AlignmentFrame>& frames, const Eigen::Vector3d& p_BC,
                     double gravity_mps2, double max_gravity_error_mps2, Alignment* alignment,
                     std::string* why);

// Refines `alignment` (its g_L gives the initial direction) with |g_L| = gravity_mps2. False when the scale
// turns non-positive or a solve fails.
bool RefineGravity(const std::vector<AlignmentFrame>& frames, const Eigen::Vector3d& p_BC,
                   double gravity_mps2, int iterations, Alignment* alignment, std::string* why);

// Two unit vectors spanning the plane orthogonal to the unit vector n.
void TangentBasis(const Eigen::Vector3d& n, Eigen::Vector3d* b1, Eigen::Vector3d* b2);

}  // namespace vigil::estimator
