// reproduction.md: the paper's claims (claims.h) judged on a sweep of the paper's grid, with the ablations
// that explain the claims that do not hold.
//
// Written beside summary.md by `vigil sweep`, `vigil paper` and `vigil tables` when the sweep has the paper's
// groups (noise_0_1, noise_1_10, noise_50_10) and methods (trunc, dtw, original); other sweeps get none.
// Ablations:
//  - vigil's variants of the same methods, when the sweep has them: every claim again with trunc ->
//    relative_threshold and dtw -> normalized_dtw (one at a time and both);
//  - the estimator's IMU noise model: when DIR/noise_ablation/ holds a sweep whose groups are
//    "<glitch setting>-<noise model>" (configs/paper_noise_sweep.yaml), table 2 and every claim per model,
//    and whether a mis-set estimator reproduces the paper's collapse of original at N(50,10) (18.05 m).
// Other estimators: when the sweep also has methods <prefix>_trunc, <prefix>_dtw and <prefix>_original (an
// external estimator behind the same detectors), every claim and variant again for each prefix, and one table
// of each claim's verdict per estimator.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "experiments/sweeps/sweep_spec.h"
#include "report/claims.h"

namespace vigil::report {

// The per-seed results of the sweep in `dir` (spec = its sweep.yaml).
SeedResults ReadSeedResults(const std::filesystem::path& dir, const experiments::SweepSpec& spec);

// Splits results whose groups are "<setting>-<label>" by label (the noise ablation): label -> results with
// the groups renamed to "<setting>".
std::map<std::string, SeedResults> SplitByLastGroupLabel(const SeedResults& results);

// The results of another estimator of the sweep: its methods "<prefix>_<method>" renamed "<method>", every
// other method left out (configs/estimators_glitch_study.yaml names OpenVINS's methods openvins_trunc, ...).
SeedResults EstimatorResults(const SeedResults& results, const std::string& prefix);

// Whether `results` has the paper's groups and methods.
bool HasPaperGrid(const SeedResults& results);

// The markdown (see above). `noise_models` may be empty (no noise ablation).
std::string ReproductionMarkdown(const std::string& sweep, std::size_t seeds, const SeedResults& results,
                                 const std::map<std::string, SeedResults>& noise_models);

// Writes DIR/reproduction.md atomically when the sweep in `dir` has the paper's grid; returns whether it did.
bool WriteReproduction(const std::filesystem::path& dir, const experiments::SweepSpec& spec);

}  // namespace vigil::report
