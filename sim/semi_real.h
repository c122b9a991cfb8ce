// Semi-real datasets: a recording's own IMU, with camera tracks synthesized along its recorded ground truth.
//
// With imu.source: recording, Simulate() (sim/simulator.h) reads the recording named by imu.recording (a
// EuRoC folder as published, or a vigil dataset directory; core/euroc.h ReadRecording) instead of
// synthesizing an IMU, and cuts a window of it:
//   - window: the ground-truth rows within [t_gt0 + recording_start_s, t_gt0 + recording_start_s +
//   duration_s]
//     (t_gt0 = the first ground-truth row); the ground truth of the dataset is these rows, as recorded;
//   - IMU: the recorded samples spanning the window (the last sample at or before its start to the first at
//     or after its end), values and timestamps as recorded; it must cover the window;
//   - camera: the recording's model (intrinsics, lens distortion, T_BC, resolution, rate) with the config's
//     camera.pixel_noise_px; the other camera.* keys are not used;
//   - frame times (RecordedFrameTimes): the recording's own camera times (cam0/data.csv, or the frames of a
//     vigil dataset) where they cover, extended before and after by the ground truth's timestamps when the
//     ground truth is at the camera rate (EuRoC's ground truth thinned to the camera times), else by the
//     camera rate from the nearest recorded frame; never snapped to a grid;
//   - landmarks: landmarks.* around the window's ground-truth positions (stream "landmarks");
//   - tracks: ideal projections at each frame time of the ground-truth pose there (linear / slerp between
//     ground-truth rows when the frame falls between them), plus pixel noise (stream "pixels";
//     camera_simulator.h ObserveLandmarks).
// Then the glitch.* and faults.* stages run on the recorded IMU exactly as on a simulated one
// (sim/imu_faults.h); imu_clean is the recorded stream (with the faults that touch both streams: scale,
// quantization, timing). The timing faults take the window's mean IMU rate as their period.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "core/euroc.h"
#include "sim/sim_options.h"

namespace vigil::sim {

// The recorded part of a semi-real dataset (before any fault or synthesized camera track).
struct RecordedWindow {
  ImuStream imu;                        // recorded samples spanning the window
  std::vector<NavState> groundtruth;    // recorded rows inside the window
  CameraModel camera;                   // the recording's camera, pixel noise from the options
  std::vector<int64_t> frame_times_ns;  // camera frame times inside the window
};

// The camera frame times of `recording` over its ground truth's span (the rule of this header's comment).
std::vector<int64_t> RecordedFrameTimes(const Recording& recording);

// Reads imu.recording and cuts the window of `options`. Throws InputError "FILE:LINE: key: reason" for a
// recording without ground truth or camera, a window beyond the ground truth, an IMU that does not cover the
// window, or a recorded camera time outside the IMU's span.
RecordedWindow ReadRecordedWindow(const SimOptions& options);

// The semi-real dataset of `options` (imu.source recording) and `seed`.
Dataset SimulateSemiReal(const SimOptions& options, uint64_t seed);

}  // namespace vigil::sim
