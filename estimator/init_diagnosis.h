// Why a run's estimator never initialized, in the words of its input.
//
// The initializer only reports its last failed step ("sfm: no reference frame ..."). A user needs the
// cause behind it, read from the run's input over the camera frames inside the IMU's time span:
//   - no frames, or fewer than the initialization window holds;
//   - too few features: no frame holds more than vins.min_correspondences tracks;
//   - the platform did not move: no feature moved more than kStationaryDisplacement_px from where it was
//     first seen (a platform standing still for the whole recording: a stationary start);
//   - not enough parallax: features moved, but the initializer never found a frame pair with
//     vins.min_parallax_px of mean parallax (pure rotation, or a scene far away);
//   - IMU excitation too low / alignment: structure from motion worked but the visual-inertial alignment
//     (scale, gravity, velocities) did not;
//   - structure from motion failed (PnP, bundle adjustment), or another initializer step.
// The last attempt's own reason always follows the cause.
#pragma once

#include <string>

#include "core/types.h"
#include "estimator/estimator_input.h"
#include "estimator/estimator_options.h"

namespace vigil::estimator {

// Below this largest feature displacement [px] over the whole span the platform is taken to stand still. A
// real tracker drifts too: on EuRoC V1_01's 4.7 s standstill (rotors running) the median track moved at most
// 1.9 px; a platform that moves enough to initialize moves features by tens of pixels (vins.min_parallax_px).
inline constexpr double kStationaryDisplacement_px = 4.0;

// What DiagnoseNoInitialization measured on the input.
struct InitEvidence {
  int frames = 0;                    // camera frames inside the IMU's time span
  int max_features = 0;              // most tracks in one of them
  double max_displacement_px = 0.0;  // largest median displacement of tracks from where they were first seen
  double gyro_std_radps = 0.0;       // norm of the per-axis standard deviations over the span
  double accel_std_mps2 = 0.0;
  double span_s = 0.0;  // time from the first to the last of those frames
};

InitEvidence MeasureInitEvidence(const EstimatorInput& input, const ImuStream& imu);

// "CAUSE (figures); last attempt: REASON". `window_frames`: frames the initialization window holds;
// `last_attempt`: the initializer's last failure reason (empty when it never ran).
std::string DiagnoseNoInitialization(const EstimatorOptions& options, const InitEvidence& evidence,
                                     int window_frames, const std::string& last_attempt);

}  // namespace vigil::estimator
