// Dead reckoning of a synthesized IMU against its own ground truth, for the tests that check that an ideal
// IMU integrates back to the trajectory it was made from.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/so3.h"
#include "sim/imu_synthesizer.h"

namespace vigil::sim {

// Deviation from the ground truth over the whole stream: largest and rms.
struct IntegrationError {
  double p_m = 0, v_mps = 0, rot_rad = 0;              // largest
  double p_rms_m = 0, v_rms_mps = 0, rot_rms_deg = 0;  // rms over every sample after the first
};

// Dead-reckons the IMU with the midpoint rule from the first ground-truth state (biases taken as zero).
inline IntegrationError IntegrateMidpoint(const ImuSynthesis& s, double g) {
  const Eigen::Vector3d g_W(0, 0, -g);
  Eigen::Vector3d p = s.groundtruth[0].p_W, v = s.groundtruth[0].v_W;
  Eigen::Quaterniond q = s.groundtruth[0].q_WB;
  double ss_p = 0, ss_v = 0, ss_r = 0;
  IntegrationError e;
  for (std::size_t k = 0; k + 1 < s.imu.size(); ++k) {
    const ImuSample &m0 = s.imu[k], &m1 = s.imu[k + 1];
    const double dt = NsToS(m1.t_ns - m0.t_ns);
    const Eigen::Quaterniond q1 = (q * ExpQ(0.5 * (m0.w_B + m1.w_B) * dt)).normalized();
    const Eigen::Vector3d a_W = 0.5 * (q * m0.a_B + q1 * m1.a_B) + g_W;
    p += v * dt + 0.5 * a_W * dt * dt;
    v += a_W * dt;
    q = q1;
    const NavState& gt = s.groundtruth[k + 1];
    const double dp = (p - gt.p_W).norm(), dv = (v - gt.v_W).norm(), dr = AngleOf(gt.q_WB.conjugate() * q);
    e.p_m = std::max(e.p_m, dp);
    e.v_mps = std::max(e.v_mps, dv);
    e.rot_rad = std::max(e.rot_rad, dr);
    ss_p += dp * dp;
    ss_v += dv * dv;
    ss_r += dr * dr;
  }
  const double n = static_cast<double>(s.imu.size() - 1);
  e.p_rms_m = std::sqrt(ss_p / n);
  e.v_rms_mps = std::sqrt(ss_v / n);
  e.rot_rms_deg = std::sqrt(ss_r / n) * 180.0 / EIGEN_PI;
  return e;
}

}  // namespace vigil::sim
