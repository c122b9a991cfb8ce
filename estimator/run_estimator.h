// One call that runs the sliding-window estimator over a whole recording.
#pragma once

#include <functional>

#include "estimator/estimator_input.h"
#include "estimator/estimator_options.h"

namespace vigil::estimator {

// Feeds `input` frame by frame to an Estimator. Never throws for numerical trouble: a diverged run returns
// ok = false with a reason and the states estimated so far. Throws InputError for inconsistent input
// (unordered timestamps, groundtruth init without ground truth).
EstimatorResult RunEstimator(const EstimatorOptions& options, const EstimatorInput& input);
// The same, calling `after_tracked_frame` with the estimator after every frame it tracked; when it returns
// false the run ends there (the per-stage benchmarks time one window this way: bench/estimator_stages.h).
class Estimator;
EstimatorResult RunEstimator(const EstimatorOptions& options, const EstimatorInput& input,
                             const std::function<bool(Estimator&)>& after_tracked_frame);

}  // namespace vigil::estimator
