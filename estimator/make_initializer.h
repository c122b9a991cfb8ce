// The one place that turns `estimator.init` into an Initializer.
#pragma once

#include <memory>

#include "estimator/estimator_input.h"
#include "estimator/estimator_options.h"
#include "estimator/initializer.h"

namespace vigil::estimator {

// Throws InputError when the chosen initializer cannot work with `input` (groundtruth without ground truth).
std::unique_ptr<Initializer> MakeInitializer(const EstimatorOptions& options, const EstimatorInput& input);

}  // namespace vigil::estimator
