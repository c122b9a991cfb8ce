#include "estimator/run_estimator.h"

#include <cmath>
#include <exception>
#include <map>
#include <string>

#include "core/error.h"
#include "core/format.h"
#include "estimator/estimator.h"
#include "estimator/imu_interval.h"
#include "estimator/make_initializer.h"

namespace vigil::estimator {
namespace {

void CheckInput(const EstimatorInput& input) {
  if (input.imu.size() < 2) throw InputError("estimator: the IMU stream needs at least two samples");
  for (std::size_t k = 1; k < input.imu.size(); ++k)
    if (input.imu[k].t_ns <= input.imu[k - 1].t_ns)
      throw InputError("estimator: IMU timestamps not strictly increasing at sample " + std::to_string(k));
  for (std::size_t k = 1; k < input.frames.size(); ++k)
    if (input.frames[k].t_ns <= input.frames[k - 1].t_ns)
      throw InputError("estimator: camera frame timestamps not strictly increasing at frame " +
                       std::to_string(k));
  const std::string camera_problem = input.camera.Validate();
  if (!camera_problem.empty()) throw InputError("estimator: camera: " + camera_problem);
}

}  // namespace

EstimatorResult RunEstimator(const EstimatorOptions& options, const EstimatorInput& input) {
  CheckInput(input);
  const double imu_rate_hz =
      static_cast<double>(input.imu.size() - 1) / NsToS(input.imu.back().t_ns - input.imu.front().t_ns);
  Estimator estimator(options, input.camera, ResolveImuNoise(options.imu_noise, input.imu_noise, imu_rate_hz),
                      input.gravity_mps2, imu_rate_hz, MakeInitializer(options, input));
  EstimatorResult result;
  try {
    for (const CameraFrame& frame : input.frames) {
      if (!ImuCovers(input.imu, frame.t_ns)) continue;
      ++result.frames;
      std::map<int, Eigen::Vector2d> features_n;
      for (const FeatureObservation& obs : frame.features)
        features_n[obs.id] = input.camera.Normalize(obs.uv_px);
      const FrameStatus status = estimator.AddFrame(frame.t_ns, features_n, input.imu);
      if (status == FrameStatus::kFailed) {
        result.ok = false;
        result.failure_reason = estimator.failure_reason();
        break;
      }
      if (status != FrameStatus::kTracking) continue;
      const NavState state = estimator.newest_state();
      result.states.push_back(state);
      result.trajectory.push_back(StampedPose{state.t_ns, state.p_W, state.q_WB});
    }
  } catch (const std::exception& e) {
    // Numerical trouble must not escape as a crash: the run fails with the reason.
    result.ok = false;
    result.failure_reason = std::string("estimator error: ") + e.what();
  }
  if (result.ok && result.states.empty()) {
    result.ok = false;
    result.failure_reason = "the estimator never initialized";
  }
  if (estimator.initialized_at_ns()) result.initialized_at_s = NsToS(*estimator.initialized_at_ns());
  result.resets = estimator.resets();
  result.keyframes = estimator.keyframes();
  result.marginalization_failures = estimator.marginalization_failures();
  result.timing = estimator.timing();
  return result;
}

}  // namespace vigil::estimator
