// A DTW template library: k templates of normal motion plus the calibrated detection threshold.
//
// Built from clean (glitch-free) IMU data by BuildTemplates():
//  1. The clean stream is cut into non-overlapping slices of M samples (the tail is dropped); at most
//     max_build_slices of them, evenly spread, are used. Each slice is normalized (slice_features.h) and
//     shortened to N rows by area averaging: these are the candidate templates.
//  2. k-medoids under the DTW distance: the k candidates minimizing the sum over the slices of the distance
//  to
//     their best template, i.e. exactly the detector's criterion. A greedy start (add the candidate that
//     lowers the sum most, k times) is followed by swap passes (PAM: the best improving medoid/candidate swap
//     per pass).
//  3. Threshold: for every slice, the best distance to a template not cut from that slice itself
//     (leave-self-out, so a template does not vouch for its own slice); threshold = threshold_margin x the
//     threshold_quantile quantile (nearest rank) of those distances.
// Everything is deterministic. For simulated experiments the clean data must come from a different seed than
// the run the library is used on (no leakage).
//
// File format (YAML, written by `vigil templates`, read by ReadTemplateLibrary):
//   format: vigil-dtw-templates-1
//   source: <where the clean data came from>
//   slice_length: M, template_length: N, dims: d, channels: [ax, ay, az(, wx, wy, wz)],
//   normalization: none | median | linear, threshold: <distance>,
//   calibration: {slices, quantile, quantile_distance, margin},
//   templates: [ [[row 0: d numbers], ... N rows], ... k templates ]   (normalized units: m/s^2, rad/s)
#pragma once

#include <string>
#include <vector>

#include "core/types.h"
#include "detectors/detector_options.h"

namespace vigil::detectors {

struct TemplateLibrary {
  int slice_length = 40;     // M
  int template_length = 10;  // N
  int dims = 6;              // d: 3 (acc) or 6 (acc + gyro)
  SliceNormalization normalization = SliceNormalization::kLinear;
  double threshold = 0.0;      // DTW distance above which a slice is abnormal
  std::vector<double> values;  // k x N x d, template t row j channel c at (t N + j) d + c

  // Provenance of the threshold.
  std::string source;
  int calibration_slices = 0;
  double calibration_quantile = 0.0, calibration_quantile_distance = 0.0, calibration_margin = 0.0;

  int count() const {
    return dims > 0 && template_length > 0 ? static_cast<int>(values.size()) / (template_length * dims) : 0;
  }
  const double* Template(int t) const {
    return values.data() + static_cast<std::size_t>(t) * template_length * dims;
  }
};

// Builds a library from clean IMU data (see above). InputError when the options are invalid (dims not 3 or 6,
// template_length > slice_length) or when `clean` has fewer than k + 1 slices.
TemplateLibrary BuildTemplates(const ImuStream& clean, const DtwOptions& options);

// Reads a library file; InputError "file:line: key: reason" on a bad file.
TemplateLibrary ReadTemplateLibrary(const std::string& path);
// The YAML text of a library (ReadTemplateLibrary reads it back exactly: numbers in round-trip form).
std::string TemplateLibraryYaml(const TemplateLibrary& library);
// The first line of every file TemplateLibraryYaml writes (how `vigil templates --force` recognises one).
inline constexpr const char* kTemplateLibraryFirstLine = "# vigil DTW template library";

// The best-template distances (double precision, Algorithm 1) of every complete slice of `stream`, after
// the library's normalization: the distribution the threshold is compared with.
std::vector<double> SliceDistances(const TemplateLibrary& library, const ImuStream& stream);

}  // namespace vigil::detectors
