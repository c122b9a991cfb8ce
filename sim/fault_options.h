// Options of the low-cost IMU fault models (section `faults` of a run config), besides the paper's offset
// glitches (section `glitch`). Every model is off by default, and then the simulation is bit-identical to one
// without the model: no random stream is drawn, no sample is touched. How the models combine: imu_faults.h.
#pragma once

#include <string>
#include <vector>

#include "core/config.h"

namespace vigil::sim {

// Typical full-scale ranges of low-cost MEMS parts (docs/references.md, "Low-cost IMU ranges").
enum class SaturationPreset { kNone, kLowCost4g, kLowCost16g };

// Clipping of each axis to +-range (an ADC at full scale). 0 means unbounded.
struct SaturationOptions {
  SaturationPreset preset = SaturationPreset::kNone;
  double accel_range_mps2 = 0.0;  // [m/s^2]
  double accel_range_g = 0.0;     // the same in units of gravity_mps2 (set one of the two)
  double gyro_range_dps = 0.0;    // [deg/s]

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Enum("preset", preset,
           config::EnumNames<SaturationPreset>{{"none", SaturationPreset::kNone},
                                               {"lowcost_4g", SaturationPreset::kLowCost4g},
                                               {"lowcost_16g", SaturationPreset::kLowCost16g}},
           "full-scale ranges of a low-cost part: lowcost_4g (+-4 g, +-2000 deg/s), lowcost_16g (+-16 g, "
           "+-2000 deg/s), or none (the *_range keys below; 0 = unbounded)");
    v.Field("accel_range_mps2", accel_range_mps2,
            "accelerometer full-scale range per axis [m/s^2] (0: unbounded; must exceed gravity)",
            Bounds::Closed(0.0, 1e6));
    v.Field("accel_range_g", accel_range_g,
            "accelerometer full-scale range per axis in units of gravity_mps2 [g] (alternative to "
            "accel_range_mps2)",
            Bounds::Closed(0.0, 1e5));
    v.Field("gyro_range_dps", gyro_range_dps, "gyro full-scale range per axis [deg/s] (0: unbounded)",
            Bounds::Closed(0.0, 1e6));
  }
};

// Rounding of every sample to a multiple of the least significant bit. 0 means no quantization; otherwise the
// LSB is at least kMinQuantizationLsb (ValidateFaultOptions).
inline constexpr double kMinQuantizationLsb = 1e-6;
struct QuantizationOptions {
  double accel_lsb_mps2 = 0.0;  // [m/s^2]
  double gyro_lsb_dps = 0.0;    // [deg/s]

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("accel_lsb_mps2", accel_lsb_mps2, "accelerometer resolution (LSB) [m/s^2] (0: none)",
            Bounds::Closed(0.0, 100.0));
    v.Field("gyro_lsb_dps", gyro_lsb_dps, "gyro resolution (LSB) [deg/s] (0: none)",
            Bounds::Closed(0.0, 100.0));
  }
};

// Constant calibration errors: measured = (I + diag(scale)) (I + N) sensed, with N symmetric, zero diagonal,
// N_yz = N_zy = misalignment[0], N_zx = misalignment[1], N_xy = misalignment[2] (non-orthogonal axes; a
// rotation of the whole triad would be a mounting error, which vigil's camera-IMU extrinsics already carry).
struct ScaleMisalignmentOptions {
  // The largest errors of this small-error model.
  static constexpr double kMaxScaleError = 0.5;
  static constexpr double kMaxMisalignment_deg = 10.0;

  std::vector<double> accel_scale = {0.0, 0.0, 0.0};             // scale-factor error per axis [fraction]
  std::vector<double> gyro_scale = {0.0, 0.0, 0.0};              // [fraction]
  std::vector<double> accel_misalignment_deg = {0.0, 0.0, 0.0};  // yz, zx, xy [deg]
  std::vector<double> gyro_misalignment_deg = {0.0, 0.0, 0.0};   // [deg]

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("accel_scale", accel_scale,
            "accelerometer scale-factor error per axis x, y, z (3 numbers; 0.01 = +1 %) [fraction]",
            Bounds::Closed(-kMaxScaleError, kMaxScaleError));
    v.Field("gyro_scale", gyro_scale, "gyro scale-factor error per axis x, y, z (3 numbers) [fraction]",
            Bounds::Closed(-kMaxScaleError, kMaxScaleError));
    v.Field("accel_misalignment_deg", accel_misalignment_deg,
            "accelerometer axis non-orthogonality of the pairs yz, zx, xy (3 numbers) [deg]",
            Bounds::Closed(-kMaxMisalignment_deg, kMaxMisalignment_deg));
    v.Field("gyro_misalignment_deg", gyro_misalignment_deg,
            "gyro axis non-orthogonality of the pairs yz, zx, xy (3 numbers) [deg]",
            Bounds::Closed(-kMaxMisalignment_deg, kMaxMisalignment_deg));
  }
};

// Timestamp faults of consumer IMU drivers. Each has its own random stream, drawn only when it is on. The
// first and the last sample are never affected (they bound the recording and its camera frames).
struct TimingFaultOptions {
  double drop_rate = 0.0;       // probability per sample that it is lost
  double duplicate_rate = 0.0;  // probability per sample that it carries the previous sample's timestamp
  double jitter_std_s = 0.0;    // std of a Gaussian timestamp error, clipped to +-0.45 sample periods [s]

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    // At most half: beyond, what is left is no longer an IMU stream a run can read.
    v.Field("drop_rate", drop_rate, "probability per IMU sample that it is dropped",
            Bounds::Closed(0.0, 0.5));
    v.Field("duplicate_rate", duplicate_rate,
            "probability per IMU sample that it is stamped with the previous sample's timestamp",
            Bounds::Closed(0.0, 0.5));
    v.Field(
        "jitter_std_s", jitter_std_s,
        "std of the Gaussian timestamp jitter, clipped to +-0.45 IMU periods so that the order is kept [s]",
        Bounds::Closed(0.0, 1.0));
  }
};

// Irregular camera frames (sim/camera_timing.h): frames taken off the nominal rate's grid, and lost frames.
// The first and the last frame are never affected.
struct CameraTimingOptions {
  double drop_rate = 0.0;     // probability per frame that it is lost
  double jitter_std_s = 0.0;  // std of a Gaussian error of each frame's time, clipped to +-0.45 periods [s]

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("drop_rate", drop_rate, "probability per camera frame that it is lost", Bounds::Probability());
    v.Field("jitter_std_s", jitter_std_s,
            "std of the Gaussian error of each camera frame's time (the tracks are seen at the jittered "
            "time), clipped to +-0.45 camera periods [s]",
            Bounds::NonNegative());
  }
};

struct FaultOptions {
  ScaleMisalignmentOptions scale;
  SaturationOptions saturation;
  QuantizationOptions quantization;
  TimingFaultOptions timing;
  CameraTimingOptions camera;

  template <class V>
  void Visit(V& v) {
    v.Section("scale", scale, "constant scale-factor and axis-misalignment errors");
    v.Section("saturation", saturation, "clipping at the sensor's full-scale range");
    v.Section("quantization", quantization, "rounding to the sensor's resolution");
    v.Section("timing", timing, "dropped samples, duplicated and jittered timestamps");
    v.Section("camera", camera, "irregular camera frames: jittered frame times and dropped frames");
  }
};

// The accelerometer range in m/s^2 (preset, accel_range_mps2 or accel_range_g x gravity; 0: unbounded) and
// the gyro range in rad/s (0: unbounded).
double AccelRangeMps2(const SaturationOptions& options, double gravity_mps2);
double GyroRangeRadps(const SaturationOptions& options);

// Cross-field checks of `faults` (key names relative to the section); empty when valid, else "key: reason".
std::string ValidateFaultOptions(const FaultOptions& options, double gravity_mps2);

}  // namespace vigil::sim
