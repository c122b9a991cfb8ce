// The DTW template detector, streaming with a latency of one slice. With normalization none (the default) it
// is the paper's DTW as literally as its text allows; with normalization linear it is vigil's normalized DTW.
//
// The stream is cut into non-overlapping slices of M samples. Each slice (d channels, after the library's
// normalization, slice_features.h) is compared with every template of the library under Algorithm 1
// (DtwMatcher). When the best distance exceeds the threshold, the slice is abnormal: all its M samples are
// flagged and, on the d compared channels, replaced by
//     the best template aligned to the slice + the slice's baseline (0 for normalization none),
// where the template is aligned to the slice along the optimal warping path (sample i takes the mean of the
// template rows the path matches with it) and, for a normalization other than none, only its shape is kept
// (its own baseline removed). Channels not compared (the gyro when d = 3) pass through.
//
// The paper's DTW (normalization none, k = 10, N = 10, M = 40, d = 6 in simulation): raw slices ("the
// concatenation of signals"), "the complete slice ... replaced by the best fitting template". Two points the
// paper leaves open, and the choices made:
//  - How a template of N = 10 rows replaces a slice of M = 40 samples: along the DTW warping path of the very
//    comparison that selected it (each sample gets the template rows matched with it), i.e. the template as
//    the distance itself stretches it over the slice. Repeating or resampling the rows would be equally
//    literal but would ignore the alignment the detector just computed.
//  - The threshold: the paper gives no value or rule. It is calibrated on clean data like vigil's
//    (template_library.h: margin x a quantile of the leave-self-out best distances of clean slices), which is
//    the least arbitrary choice that needs nothing from the data being cleaned.
// Raw slices make the distance depend on where the robot is on its trajectory: templates must cover the same
// motion, and a steady level no template has is abnormal and overwritten by the template's level.
//
// vigil's normalized DTW (normalization linear): slice and templates compared after removing a robust
// per-channel line, and the replacement is the template's shape on the slice's own line. The slice's
// baseline is fitted with medians, so it is the slice's low-frequency content without the glitch: the
// replacement keeps the motion and drops the spike. Removing the template's own baseline matters: the best
// template for a slice with a large positive spike tends to be one with a high row, and adding its offset
// would bias every replaced slice in the direction of the glitches (measured ~0.2 m/s^2 on az with N(50, 10)
// glitches), which the estimator would integrate into drift.
//
// End of stream: the last incomplete slice (r < M samples) is judged as the window of the last M samples
// (the M - r already emitted, cleaned, plus the r new ones); only its r new samples are flagged or replaced.
// A stream shorter than M passes through unflagged.
#pragma once

#include <memory>
#include <vector>

#include "detectors/detector.h"
#include "detectors/dtw_matcher.h"
#include "detectors/slice_features.h"
#include "detectors/template_library.h"

namespace vigil::detectors {

// The distance threshold a DtwDetector uses: options.threshold when set (> 0), else the library's calibrated
// one.
double EffectiveDtwThreshold(const DtwOptions& options, const TemplateLibrary& library);

class DtwDetector final : public Detector {
 public:
  // Uses the library's geometry (k, N, M, d, normalization) and its threshold unless options.threshold > 0.
  // InputError on an invalid library.
  DtwDetector(const DtwOptions& options, const TemplateLibrary& library);

  void Push(const ImuSample& raw, std::vector<DetectedSample>* out) override;
  void Finish(std::vector<DetectedSample>* out) override;
  int latency_samples() const override { return library_.slice_length - 1; }

  double threshold() const { return threshold_; }
  // The best distance of every slice judged so far (diagnostics).
  const std::vector<double>& slice_distances() const { return slice_distances_; }

 private:
  // Judges window[0 .. M) and emits window[first_new .. M).
  void Judge(std::vector<ImuSample>& window, int first_new, std::vector<DetectedSample>* out);

  const TemplateLibrary& library_;
  double threshold_;
  DtwMatcher matcher_;
  std::vector<ImuSample> pending_;   // raw samples of the slice being filled
  std::vector<ImuSample> previous_;  // the last M emitted (cleaned) samples
  std::vector<double> slice_, replacement_, scratch_;
  std::vector<float> slice_f_;
  std::vector<int> matches_;
  SliceBaseline baseline_, template_baseline_;
  std::vector<double> slice_distances_;
};

}  // namespace vigil::detectors
