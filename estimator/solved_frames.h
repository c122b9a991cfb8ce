// Which camera frames the estimator solves (EstimatorOptions::max_frame_rate_hz).
//
// Solving every frame of a 20-30 Hz camera buys little: the window's states are relinearized at every solve
// anyway, and the frames between keyframes leave the window again. VINS-Mono's EuRoC configuration feeds its
// estimator 10 frames per second (`freq: 10`), vigil's default too. The cap holds from the first frame, so
// the initialization's window spans three times as long at 10 Hz from a 30 Hz camera (more motion for the
// gravity and scale); the frames left out are never seen by the estimator. The trajectory has the frames the
// cap lets through, as VINS-Mono's has its solved frames; with EstimatorOptions::predict_between_solves the
// frames left out get the IMU's prediction from the newest solved state (Estimator::PredictedState), so it
// keeps the camera's rate. The evaluation covers the ground truth between estimate poses close in time
// (evaluation/coverage.h) either way.
//
// With EstimatorOptions::solve_flagged_frames (vigil's rule) the cap lets through each frame whose interval
// since the last solved one holds a sample a detector flagged (AnyFlaggedSample, imu_interval.h): the IMU
// factors over flagged (replaced or suspect) data then span one camera interval, and vision holds them at the
// camera's rate. Those frames do not shift the cap's pace, and the trajectory keeps to it (unless
// predict_between_solves gives every frame a row): every run has the same pose rate, whatever its flags, so a
// sweep's pooled relative errors weigh its runs alike (docs/sweeps.md).
#pragma once

#include <cstdint>
#include <optional>

namespace vigil::estimator {

// Whether a rate of at most max_rate_hz allows a frame at t_ns, the last frame taken at last_ns (a solve
// under EstimatorOptions::max_frame_rate_hz, a covariance under covariance_rate_hz): when at least
// 0.9 / max_rate_hz has passed (always when max_rate_hz is 0). The 0.9 keeps a camera's jitter from
// skipping a frame the rate allows: a 30 Hz camera at 10 Hz gives every third frame, a 20 Hz camera every
// second one.
bool RateAllows(int64_t last_ns, int64_t t_ns, double max_rate_hz);

// The cap's pace over a run's frames, in time order: the first frame, then each frame RateAllows after the
// last one the pace took. The frames solved for their flags are not the pace's, so they do not shift it.
class FramePace {
 public:
  explicit FramePace(double max_rate_hz) : max_rate_hz_(max_rate_hz) {}
  // Whether the pace takes the frame at t_ns (and then counts from it).
  bool Take(int64_t t_ns);

 private:
  double max_rate_hz_;
  std::optional<int64_t> last_ns_;
};

}  // namespace vigil::estimator
