#include "experiments/runs/run_inputs.h"

#include <utility>

#include "core/interpolation.h"

namespace vigil::experiments {

estimator::EstimatorInput MakeEstimatorInput(const RunConfig& config, const Dataset& dataset, ImuStream imu,
                                             std::vector<uint8_t> flagged) {
  estimator::EstimatorInput input;
  input.imu = std::move(imu);
  input.frames = dataset.frames;
  input.camera = dataset.camera;
  const sim::ImuNoiseOptions& noise = config.sim.imu.noise;
  input.imu_noise.gyro_noise_density = noise.gyro_noise_density;
  input.imu_noise.accel_noise_density = noise.accel_noise_density;
  input.imu_noise.gyro_bias_random_walk = noise.gyro_bias_random_walk;
  input.imu_noise.accel_bias_random_walk = noise.accel_bias_random_walk;
  input.gravity_mps2 = config.sim.gravity_mps2;
  input.groundtruth = dataset.groundtruth;
  input.seed = config.seed;
  input.imu_flagged = std::move(flagged);
  return input;
}

Trajectory GroundTruthAtFrames(const std::vector<NavState>& groundtruth,
                               const std::vector<CameraFrame>& frames) {
  Trajectory out;
  out.reserve(frames.size());
  for (const CameraFrame& frame : frames) {
    NavState s;
    if (!InterpolateNavState(groundtruth, frame.t_ns, &s)) continue;
    out.push_back({s.t_ns, s.p_W, s.q_WB});
  }
  return out;
}

}  // namespace vigil::experiments
