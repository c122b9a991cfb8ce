#include "estimator/make_initializer.h"

#include "core/error.h"
#include "estimator/ground_truth_initializer.h"

namespace vigil::estimator {

std::unique_ptr<Initializer> MakeInitializer(const EstimatorOptions& options, const EstimatorInput& input) {
  switch (options.init) {
    case InitMode::kGroundTruth:
      if (input.groundtruth.empty())
        throw InputError(
            "estimator.init: groundtruth initialization needs ground truth, and the input has none");
      return std::make_unique<GroundTruthInitializer>(input.groundtruth, options.groundtruth_init,
                                                      input.seed);
    case InitMode::kVins:
      // The visual-inertial initializer (estimator/init/) plugs in here.
      break;
  }
  throw InputError("estimator.init: this initialization is not available in this build");
}

}  // namespace vigil::estimator
