// IMU measurements and ground truth synthesized from a motion model (formats.md's sensor model).
//
//   gyro:  w_m = w_B + b_g + n_g
//   accel: a_m = R_WB^T (a_W - g_W) + b_a + n_a,   g_W = (0, 0, -g)
//
// Samples are taken at t_k = k / rate_hz, k = 0 .. floor(duration_s * rate_hz) (timestamps rounded to integer
// nanoseconds; the motion is evaluated at the rounded time so truth and measurement agree exactly). With
// noise enabled, n ~ N(0, density^2 / dt) independently per axis and sample (stream "imu_noise"); the biases
// start at the configured initial biases and after each sample take a random-walk step b += random_walk *
// sqrt(dt) * N(0, 1) (stream "imu_bias"). The ground truth row of sample k carries the biases in effect in
// that sample. With imu.noise.switch_on_*_bias_std > 0, a N(0, std^2) draw per axis (stream
// "imu_switch_on_bias") is added to the initial biases; with imu.vibration enabled, the band-limited
// vibration of sim/vibration.h (stream "imu_vibration") is added to each measured sample. Both streams are
// used only when asked, so the default dataset is unchanged bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"
#include "sim/sim_options.h"
#include "sim/trajectory_model.h"

namespace vigil::sim {

struct ImuSynthesis {
  ImuStream imu;                      // measured: ideal + bias + white noise (no glitches)
  std::vector<NavState> groundtruth;  // one state per IMU sample, same timestamps
};

// Timestamps of the IMU samples covering [0, duration_s].
std::vector<int64_t> ImuSampleTimes(double rate_hz, double duration_s);

// What a perfect IMU reads in `state` (no bias, no noise).
ImuSample IdealImuSample(const TrajectoryState& state, double gravity_mps2, int64_t t_ns);

ImuSynthesis SynthesizeImu(const TrajectoryModel& motion, const ImuOptions& options, double duration_s,
                           double gravity_mps2, uint64_t seed);

}  // namespace vigil::sim
