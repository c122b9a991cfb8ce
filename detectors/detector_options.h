// Options of the glitch detectors and their mitigation.
//
// Every detector reads a stream of IMU samples and writes the same stream, cleaned, with one flag per sample.
// The axis order of every per-axis list is the imu.csv column order: wx, wy, wz [rad/s], ax, ay, az [m/s^2].
// Keys are documented in configs/README.md (generated from these Visit() descriptions).
#pragma once

#include <string>
#include <vector>

#include "core/config.h"

namespace vigil::detectors {

// The detectors. threshold and dtw are the paper's rules (Long et al., IFAC 2020); relative_threshold and the
// dtw detector with normalization linear are vigil's variants of them; hampel is an extra baseline.
enum class DetectorType { kNone, kThreshold, kRelativeThreshold, kDtw, kHampel };

inline const config::EnumNames<DetectorType>& DetectorTypeNames() {
  static const config::EnumNames<DetectorType> names = {
      {"none", DetectorType::kNone},
      {"threshold", DetectorType::kThreshold},
      {"relative_threshold", DetectorType::kRelativeThreshold},
      {"dtw", DetectorType::kDtw},
      {"hampel", DetectorType::kHampel}};
  return names;
}

// What a threshold detector writes in place of an abnormal value.
enum class ThresholdMitigation { kTruncate, kMean };

inline const config::EnumNames<ThresholdMitigation>& ThresholdMitigationNames() {
  static const config::EnumNames<ThresholdMitigation> names = {{"threshold", ThresholdMitigation::kTruncate},
                                                               {"mean", ThresholdMitigation::kMean}};
  return names;
}

// Where the paper's threshold detector gets its bounds.
enum class ThresholdCalibration { kClean, kManual };

inline const config::EnumNames<ThresholdCalibration>& ThresholdCalibrationNames() {
  static const config::EnumNames<ThresholdCalibration> names = {{"clean", ThresholdCalibration::kClean},
                                                                {"manual", ThresholdCalibration::kManual}};
  return names;
}

// Largest sample window a detector keeps (mean_samples, reference_samples, half_window): 100,000 samples,
// over 8 min at 200 Hz. The window is allocated when the detector starts, so a larger value is refused when
// the config is read (2e9 made the allocation fail).
inline constexpr int kMaxDetectorWindowSamples = 100000;

// Largest DTW library build: k templates, slices of M samples, clean slices clustered (the paper's k = 10,
// M = 40, vigil's default 400 slices). The build keeps a slices x slices distance matrix, and a run without a
// template file simulates 2 (k + 1) M clean samples for it (within sim's 1e7-sample limit), so larger values
// are refused when the config is read.
inline constexpr int kMaxDtwTemplates = 1000;
inline constexpr int kMaxDtwSliceSamples = 4000;
inline constexpr int kMaxDtwBuildSlices = 5000;

// The paper's threshold detector ("trunc"), per axis on the measured value itself: a value above upper[axis]
// or below lower[axis] is abnormal. Mitigation threshold: clamp to the violated bound (the paper's choice in
// its VINS integration); mean: the mean of the axis' last n output values. Bounds: calibration clean (a run
// calibrates them on the clean IMU of a glitch-free simulation of its scenario with another seed; `vigil
// templates` prints them for a recording) or manual (lower / upper as given). See threshold_detector.h.
struct ThresholdOptions {
  ThresholdCalibration calibration = ThresholdCalibration::kClean;
  std::vector<double> lower = {-4.0, -4.0, -4.0, -39.2, -39.2, -39.2};
  std::vector<double> upper = {4.0, 4.0, 4.0, 39.2, 39.2, 39.2};
  ThresholdMitigation mitigation = ThresholdMitigation::kTruncate;
  int mean_samples = 4;
  double calibration_margin = 1.2;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Enum(
        "calibration", calibration, ThresholdCalibrationNames(),
        "clean: bounds calibrated on a glitch-free simulation of the run's scenario (seed DeriveSeed(seed, "
        "\"calibration\")); manual: lower / upper as given");
    v.Field("lower", lower,
            "manual: smallest normal measured value per axis wx,wy,wz [rad/s], ax,ay,az [m/s^2] (6 numbers; "
            "default a +-4 rad/s, +-4 g sensor range)");
    v.Field("upper", upper,
            "manual: largest normal measured value per axis wx,wy,wz [rad/s], ax,ay,az [m/s^2] (6 numbers)");
    v.Enum("mitigation", mitigation, ThresholdMitigationNames(),
           "threshold: clamp an abnormal value to the bound it violated (the paper); mean: replace it by the "
           "mean of the axis' last mean_samples output values");
    v.Field("mean_samples", mean_samples, "n of mitigation mean",
            Bounds::Closed(1, kMaxDetectorWindowSamples));
    v.Field("calibration_margin", calibration_margin,
            "calibration: bounds = centre of the clean range +- margin x its half-width, per axis",
            Bounds::AtLeast(1.0));
  }
};

// vigil's relative threshold detector (not the paper's rule), per axis. The reference of an axis is the mean
// of its last `reference_samples` normal values; a value is abnormal when |value - reference| > bounds[axis].
// Abnormal values are clamped to reference +- bound (mitigation threshold) or replaced by the reference
// (mitigation mean). Calibration from clean data: CalibrateRelativeThresholdBounds
// (relative_threshold_detector.h), also printed by `vigil templates`.
struct RelativeThresholdOptions {
  std::vector<double> bounds = {1.5, 1.5, 1.5, 2.5, 2.5, 2.5};
  int reference_samples = 4;
  ThresholdMitigation mitigation = ThresholdMitigation::kTruncate;
  int max_run = 8;
  double calibration_margin = 1.5;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("bounds", bounds,
            "largest normal abs(value - reference) per axis wx,wy,wz [rad/s], ax,ay,az [m/s^2] (6 numbers)",
            Bounds::Positive());
    v.Field("reference_samples", reference_samples,
            "n: the reference is the mean of the last n normal values",
            Bounds::Closed(1, kMaxDetectorWindowSamples));
    v.Enum("mitigation", mitigation, ThresholdMitigationNames(),
           "threshold: clamp to reference +- bound; mean: replace by the mean of the last n normal values");
    v.Field(
        "max_run", max_run,
        "after this many consecutive abnormal values an axis accepts the new level (re-seeds its reference)",
        Bounds::AtLeast(1));
    v.Field("calibration_margin", calibration_margin,
            "calibration: bound = margin x largest abs(value - reference) seen on clean data",
            Bounds::AtLeast(1.0));
  }
};

// How a slice (and a template) is normalized before the DTW comparison.
enum class SliceNormalization { kNone, kMedian, kLinear };

inline const config::EnumNames<SliceNormalization>& SliceNormalizationNames() {
  static const config::EnumNames<SliceNormalization> names = {{"none", SliceNormalization::kNone},
                                                              {"median", SliceNormalization::kMedian},
                                                              {"linear", SliceNormalization::kLinear}};
  return names;
}

// The DTW detector. The stream is cut into non-overlapping slices of `slice_length` samples; each
// slice (d = `dims` channels: ax, ay, az, then wx, wy, wz when d = 6) is compared with `templates` templates
// of `template_length` rows under the DTW distance of Algorithm 1; a best distance above the threshold marks
// the slice abnormal and replaces it by the best template aligned along the optimal warping path.
// normalization none (the default) is the paper's DTW: raw slices, replaced by the raw best template;
// normalization linear is vigil's normalized DTW (sweep method `normalized_dtw`): slices compared after
// removing a robust per-channel line, replaced by the template's shape on the slice's own line.
// The defaults are the paper's simulation setting k = 10, N = 10, M = 40, d = 6; its real-robot setting is
// k = 10, N = 40, M = 40, d = 3 (`--set detector.dtw.template_length=40 --set detector.dtw.dims=3`).
// k, N, M, d and the normalization are build parameters of a template library: a library read from a file
// carries its own, which then apply.
struct DtwOptions {
  std::string templates_file;
  int templates = 10;
  int template_length = 10;
  int slice_length = 40;
  int dims = 6;
  SliceNormalization normalization = SliceNormalization::kNone;
  double threshold = 0.0;
  double threshold_quantile = 0.99;
  double threshold_margin = 1.5;
  int max_build_slices = 400;
  int swap_passes = 10;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("templates_file", templates_file,
            "template library written by `vigil templates` (empty: the run builds one from a glitch-free "
            "simulation with seed DeriveSeed(seed, \"templates\")); relative to the config file, or "
            "$VIGIL_DATA/...");
    v.Field("templates", templates, "k: number of templates (library build)",
            Bounds::Closed(1, kMaxDtwTemplates));
    v.Field("template_length", template_length, "N: rows per template, <= slice_length (library build)",
            Bounds::AtLeast(1));
    v.Field("slice_length", slice_length,
            "M: samples per slice; bounded latency of the detector (library build)",
            Bounds::Closed(2, kMaxDtwSliceSamples));
    v.Field("dims", dims, "d: 3 (acc) or 6 (acc + gyro) channels compared (library build)",
            Bounds::Closed(3, 6));
    v.Enum("normalization", normalization, SliceNormalizationNames(),
           "per-channel normalization of slices and templates before comparing: none (the paper's raw "
           "slices, replaced by the raw best template), median (subtract the median), linear (vigil's "
           "normalized DTW: subtract the robust line through the medians of both halves; the replacement "
           "keeps the slice's line) (library build)");
    v.Field("threshold", threshold,
            "DTW distance above which a slice is abnormal (0: the library's calibrated one)",
            Bounds::NonNegative());
    v.Field("threshold_quantile", threshold_quantile,
            "calibration: quantile of the best-template distances of clean slices (library build)",
            Bounds::Probability());
    v.Field("threshold_margin", threshold_margin,
            "calibration: threshold = margin x that quantile (library build)", Bounds::AtLeast(1.0));
    v.Field("max_build_slices", max_build_slices,
            "library build: at most this many clean slices (evenly spread) are clustered",
            Bounds::Closed(1, kMaxDtwBuildSlices));
    v.Field("swap_passes", swap_passes, "library build: k-medoids swap passes after the greedy start",
            Bounds::NonNegative());
  }
};

// Hampel filter per axis: over a centred window of 2 h + 1 samples, sigma = 1.4826 MAD; a value farther than
// n_sigma sigma from the window median is abnormal and replaced by the median.
// The defaults (h = 10, n_sigma = 5) are wider than the textbook 3 sigma: the MAD of a short window is a
// noisy, low-biased scale estimate and six axes are tested per sample, so 3 sigma flags several percent of
// clean samples (measured on the paper's noise levels); 5 sigma keeps false alarms near 0.5 %.
struct HampelOptions {
  int half_window = 10;
  double n_sigma = 5.0;

  template <class V>
  void Visit(V& v) {
    using config::Bounds;
    v.Field("half_window", half_window, "h: the window is 2 h + 1 samples; latency h samples",
            Bounds::Closed(1, kMaxDetectorWindowSamples));
    v.Field("n_sigma", n_sigma, "abnormal beyond n_sigma x 1.4826 MAD from the median", Bounds::Positive());
  }
};

struct DetectorOptions {
  DetectorType type = DetectorType::kNone;
  std::string calibration_dataset;
  ThresholdOptions threshold;
  RelativeThresholdOptions relative_threshold;
  DtwOptions dtw;
  HampelOptions hampel;

  template <class V>
  void Visit(V& v) {
    v.Enum("type", type, DetectorTypeNames(),
           "glitch detector + mitigation applied to the IMU stream: threshold (the paper's trunc: value "
           "bounds), relative_threshold (vigil: bound on the deviation from a running mean), dtw (templates; "
           "see dtw.normalization), hampel (rolling median / MAD)");
    v.Field("calibration_dataset", calibration_dataset,
            "runs on a recording (--dataset): the glitch-free reference that threshold bounds (calibration "
            "clean) and dtw templates (no templates_file) are calibrated on: a dataset directory (its "
            "imu_clean.csv, else imu.csv), a EuRoC folder (mav0/imu0/data.csv) or an IMU CSV. Empty: the "
            "recording's own imu_clean.csv, else the run refuses. Relative to the config file, or "
            "$VIGIL_DATA/...; "
            "simulated runs ignore it");
    v.Section("threshold", threshold,
              "the paper's threshold detector (trunc): bounds on the measured value, clamp or mean");
    v.Section("relative_threshold", relative_threshold,
              "vigil's relative threshold: bound on abs(value - mean of the last n normal values)");
    v.Section("dtw", dtw,
              "DTW template detector: normalization none = the paper's dtw, linear = vigil's normalized DTW");
    v.Section("hampel", hampel, "Hampel filter (rolling median / MAD)");
  }
};

}  // namespace vigil::detectors
