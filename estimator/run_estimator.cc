#include "estimator/run_estimator.h"

#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/format.h"
#include "estimator/estimator.h"
#include "estimator/imu_interval.h"
#include "estimator/imu_trust.h"
#include "estimator/init_diagnosis.h"
#include "estimator/make_initializer.h"
#include "estimator/rest_noise.h"
#include "estimator/solved_frames.h"

namespace vigil::estimator {
namespace {

// The IMU samples the estimator integrates: a sample whose timestamp equals the previous one's (a duplicated
// timestamp of a consumer IMU) is dropped, keeping the first, together with its flag. Timestamps going
// backwards are an input error.
struct IntegratedImu {
  ImuStream imu;
  std::vector<uint8_t> flagged;
  int repeated = 0;
};

IntegratedImu DropRepeatedTimestamps(const EstimatorInput& input) {
  if (!input.imu_flagged.empty() && input.imu_flagged.size() != input.imu.size())
    throw InputError("estimator: imu_flagged must be empty or hold one flag per IMU sample");
  IntegratedImu out;
  for (std::size_t k = 1; k < input.imu.size(); ++k) {
    if (input.imu[k].t_ns < input.imu[k - 1].t_ns)
      throw InputError("estimator: IMU timestamps decrease at sample " + std::to_string(k));
    out.repeated += input.imu[k].t_ns == input.imu[k - 1].t_ns;
  }
  if (out.repeated == 0) return out;  // the input is used as it is
  for (std::size_t k = 0; k < input.imu.size(); ++k) {
    if (k > 0 && input.imu[k].t_ns == input.imu[k - 1].t_ns) continue;
    out.imu.push_back(input.imu[k]);
    if (!input.imu_flagged.empty()) out.flagged.push_back(input.imu_flagged[k]);
  }
  return out;
}

void CheckInput(const ImuStream& imu, const EstimatorInput& input) {
  if (imu.size() < 2) throw InputError("estimator: the IMU stream needs at least two samples");
  for (std::size_t k = 1; k < input.frames.size(); ++k)
    if (input.frames[k].t_ns <= input.frames[k - 1].t_ns)
      throw InputError("estimator: camera frame timestamps not strictly increasing at frame " +
                       std::to_string(k));
  const std::string camera_problem = input.camera.Validate();
  if (!camera_problem.empty()) throw InputError("estimator: camera: " + camera_problem);
}

}  // namespace

EstimatorResult RunEstimator(const EstimatorOptions& options, const EstimatorInput& input) {
  return RunEstimator(options, input, [](Estimator&) { return true; });
}

EstimatorResult RunEstimator(const EstimatorOptions& options, const EstimatorInput& input,
                             const std::function<bool(Estimator&)>& after_tracked_frame) {
  const IntegratedImu deduplicated = DropRepeatedTimestamps(input);
  const bool repeated = deduplicated.repeated > 0;
  const ImuStream& imu = repeated ? deduplicated.imu : input.imu;
  const std::vector<uint8_t>& flagged = repeated ? deduplicated.flagged : input.imu_flagged;
  CheckInput(imu, input);
  const ImuTrust trust = ComputeImuTrust(options.mitigation, imu, flagged);
  const double imu_rate_hz = static_cast<double>(imu.size() - 1) / NsToS(imu.back().t_ns - imu.front().t_ns);
  ImuNoiseDensities noise = ResolveImuNoise(options.imu_noise, input.imu_noise, imu_rate_hz);
  EstimatorResult result;
  result.rest_noise = MeasureRestNoise(imu, input.frames, input.camera, options.zero_velocity,
                                       options.imu_noise.at_rest, &noise);
  Estimator estimator(options, input.camera, noise, input.gravity_mps2, imu_rate_hz,
                      MakeInitializer(options, input));
  result.mitigation.repeated_timestamps = deduplicated.repeated;
  result.mitigation.inflated_samples = trust.inflated_samples;
  result.mitigation.clipped_samples = trust.clipped_samples;
  const auto output = [&](const NavState& state, const std::optional<Matrix6d>& covariance) {
    result.states.push_back(state);
    result.trajectory.push_back(StampedPose{state.t_ns, state.p_W, state.q_WB});
    if (options.pose_covariance)
      result.pose_covariances.push_back(
          covariance.value_or(Matrix6d::Constant(std::numeric_limits<double>::quiet_NaN())));
  };
  try {
    bool tracking = false;  // the newest solved frame was tracked
    // The trajectory has the paced frames, at the same rate in every run.
    FramePace pace(options.max_frame_rate_hz);
    std::optional<int64_t> last_solved_ns;
    for (const CameraFrame& frame : input.frames) {
      if (!ImuCovers(imu, frame.t_ns)) continue;
      ++result.frames;
      const bool paced = pace.Take(frame.t_ns);
      const bool after_flagged = !paced && options.solve_flagged_frames &&
                                 AnyFlaggedSample(imu, flagged, *last_solved_ns, frame.t_ns);
      if (!paced && !after_flagged) {
        if (tracking && options.predict_between_solves)
          output(estimator.PredictedState(frame.t_ns, imu, &trust.variance_scale), std::nullopt);
        continue;
      }
      ++result.solved_frames;
      last_solved_ns = frame.t_ns;
      const FrameStatus status =
          estimator.AddFrame(frame.t_ns, NormalizedFeatures(frame, input.camera), imu, &trust.variance_scale);
      tracking = status == FrameStatus::kTracking;
      if (status == FrameStatus::kFailed) {
        result.ok = false;
        result.stops = 1;
        result.failure_reason = estimator.failure_reason();
        break;
      }
      if (!tracking) continue;
      // A frame solved only for its flagged interval refines the window; it is a row of the trajectory only
      // where every frame is one (predict_between_solves).
      if (paced || options.predict_between_solves)
        output(estimator.newest_state(), estimator.newest_pose_covariance());
      if (!after_tracked_frame(estimator)) break;
    }
  } catch (const std::exception& e) {
    // Numerical trouble must not escape as a crash: the run fails with the reason.
    result.ok = false;
    result.failure_reason = std::string("estimator error: ") + e.what();
  }
  if (result.ok && result.states.empty()) {
    result.ok = false;
    result.failure_reason =
        "the estimator never initialized: " +
        DiagnoseNoInitialization(options, MeasureInitEvidence(input, imu), estimator.window_frames(),
                                 estimator.init_failure_reason());
  }
  // From the start of the recording (its first IMU sample), not the recording's clock.
  if (estimator.initialized_at_ns())
    result.initialized_at_s = NsToS(*estimator.initialized_at_ns() - imu.front().t_ns);
  result.resets = estimator.resets();
  result.failure_checks = estimator.failure_checks();
  result.keyframes = estimator.keyframes();
  result.marginalization_failures = estimator.marginalization_failures();
  result.timing = estimator.timing();
  result.mitigation.gate_tests = estimator.gating().tests;
  result.mitigation.gated_factors = estimator.gating().gated;
  result.mitigation.gated_resolves = estimator.gating().resolves;
  return result;
}

}  // namespace vigil::estimator
