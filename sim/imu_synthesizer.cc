#include "sim/imu_synthesizer.h"

#include <cmath>
#include <memory>

#include "core/random.h"
#include "sim/vibration.h"

namespace vigil::sim {

std::vector<int64_t> ImuSampleTimes(double rate_hz, double duration_s) {
  // The small tolerance keeps the last sample when duration * rate is an integer up to rounding.
  const int64_t last = static_cast<int64_t>(std::floor(duration_s * rate_hz + 1e-9));
  std::vector<int64_t> times(static_cast<std::size_t>(last + 1));
  for (int64_t k = 0; k <= last; ++k)
    times[static_cast<std::size_t>(k)] =
        static_cast<int64_t>(std::llround(static_cast<double>(k) * 1e9 / rate_hz));
  return times;
}

ImuSample IdealImuSample(const TrajectoryState& state, double gravity_mps2, int64_t t_ns) {
  const Eigen::Vector3d g_W(0.0, 0.0, -gravity_mps2);
  ImuSample s;
  s.t_ns = t_ns;
  s.w_B = state.w_B;
  s.a_B = state.q_WB.conjugate() * (state.a_W - g_W);
  return s;
}

ImuSynthesis SynthesizeImu(const TrajectoryModel& motion, const ImuOptions& options, double duration_s,
                           double gravity_mps2, uint64_t seed) {
  const std::vector<int64_t> times = ImuSampleTimes(options.rate_hz, duration_s);
  const double dt = 1.0 / options.rate_hz;
  const ImuNoiseOptions& noise = options.noise;
  const double gyro_sigma = noise.gyro_noise_density / std::sqrt(dt);
  const double accel_sigma = noise.accel_noise_density / std::sqrt(dt);
  const double gyro_walk = noise.gyro_bias_random_walk * std::sqrt(dt);
  const double accel_walk = noise.accel_bias_random_walk * std::sqrt(dt);
  Rng noise_rng(seed, "imu_noise");
  Rng bias_rng(seed, "imu_bias");

  ImuSynthesis out;
  out.imu.reserve(times.size());
  out.groundtruth.reserve(times.size());
  Eigen::Vector3d b_g = Eigen::Vector3d::Zero(), b_a = Eigen::Vector3d::Zero();
  if (noise.enabled) {  // ValidateSimOptions checks that the initial biases have 3 numbers
    b_g = Eigen::Vector3d(noise.initial_gyro_bias.at(0), noise.initial_gyro_bias.at(1),
                          noise.initial_gyro_bias.at(2));
    b_a = Eigen::Vector3d(noise.initial_accel_bias.at(0), noise.initial_accel_bias.at(1),
                          noise.initial_accel_bias.at(2));
    // Switch-on biases: their own stream, drawn only when asked, so the other streams never change.
    if (noise.switch_on_gyro_bias_std > 0.0 || noise.switch_on_accel_bias_std > 0.0) {
      Rng switch_on_rng(seed, "imu_switch_on_bias");
      const Eigen::Vector3d d_g = switch_on_rng.NormalVector3();  // draw order: gyro xyz, then accel xyz
      const Eigen::Vector3d d_a = switch_on_rng.NormalVector3();
      b_g += noise.switch_on_gyro_bias_std * d_g;
      b_a += noise.switch_on_accel_bias_std * d_a;
    }
  }
  std::unique_ptr<Vibration> vibration;
  if (options.vibration.enabled()) vibration = std::make_unique<Vibration>(options.vibration, seed);
  for (const int64_t t_ns : times) {
    const TrajectoryState x = motion.StateAt(NsToS(t_ns));
    ImuSample s = IdealImuSample(x, gravity_mps2, t_ns);
    if (noise.enabled) {
      const Eigen::Vector3d n_g = noise_rng.NormalVector3();  // draw order: gyro xyz, then accel xyz
      const Eigen::Vector3d n_a = noise_rng.NormalVector3();
      s.w_B += b_g + gyro_sigma * n_g;
      s.a_B += b_a + accel_sigma * n_a;
    }
    if (vibration) {
      Eigen::Vector3d v_w, v_a;
      vibration->At(NsToS(t_ns), &v_w, &v_a);
      s.w_B += v_w;
      s.a_B += v_a;
    }
    NavState gt;
    gt.t_ns = t_ns;
    gt.p_W = x.p_W;
    gt.q_WB = x.q_WB;
    gt.v_W = x.v_W;
    gt.b_g = b_g;
    gt.b_a = b_a;
    out.imu.push_back(s);
    out.groundtruth.push_back(gt);
    if (noise.enabled) {
      const Eigen::Vector3d step_g = bias_rng.NormalVector3();
      const Eigen::Vector3d step_a = bias_rng.NormalVector3();
      b_g += gyro_walk * step_g;
      b_a += accel_walk * step_a;
    }
  }
  return out;
}

}  // namespace vigil::sim
