// One call that runs the sliding-window estimator over a whole recording.
#pragma once

#include "estimator/estimator_input.h"
#include "estimator/estimator_options.h"

namespace vigil::estimator {

// Feeds `input` frame by frame to an Estimator. Never throws for numerical trouble: a diverged run returns
// ok = false with a reason and the states estimated so far. Throws InputError for inconsistent input
// (unordered timestamps, groundtruth init without ground truth).
EstimatorResult RunEstimator(const EstimatorOptions& options, const EstimatorInput& input);

}  // namespace vigil::estimator
