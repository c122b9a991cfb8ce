// Detector ROC from a sweep whose methods are (detector, threshold) points, read back from the runs'
// metrics.json: per method, the true-positive rate (recall over glitched samples) and the false-positive rate
// (flagged normal samples / normal samples), pooled over seeds and the sweep's axis settings by sample
// counts.
//
// Methods are grouped into curves by their label without its last '_' part ("threshold_2.5" and
// "threshold_4" make the curve "threshold"); configs/roc_paper.yaml and configs/roc_rescue.yaml follow that.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/sweeps/sweep_spec.h"

namespace vigil::experiments {

struct RocPoint {
  std::string method;  // the sweep method (one threshold)
  double tpr = 0.0, fpr = 0.0;
  double glitched = 0.0, normal = 0.0;  // pooled sample counts
  int runs = 0;
};

struct RocCurve {
  std::string detector;          // the method labels' common prefix
  std::vector<RocPoint> points;  // in the sweep's method order
};

// InputError "SWEEP:LINE: methods: LABEL: reason" unless every method label is <curve>_<point>: a curve
// name (letters, digits, '_') and a finite number (e.g. hampel_3, relative_threshold_0.5), and each method
// of a curve runs that curve's detector (the curve's name is the detector's, or the detector's with a
// variant prefix such as normalized_dtw).
void CheckRocMethodLabels(const SweepSpec& spec);

// InputError naming the sweep when no run recorded detection statistics with glitches.
std::vector<RocCurve> ReadDetectionRoc(const std::filesystem::path& dir, const SweepSpec& spec);

// roc.md: per curve, a table of threshold point, TPR, FPR (per sample) and runs.
std::string DetectionRocMarkdown(const std::vector<RocCurve>& curves);

}  // namespace vigil::experiments
