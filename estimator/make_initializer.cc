#include "estimator/make_initializer.h"

#include <utility>

#include "core/error.h"
#include "estimator/ground_truth_initializer.h"
#include "estimator/init/vins_initializer.h"
#include "estimator/static_initializer.h"

namespace vigil::estimator {

std::unique_ptr<Initializer> MakeInitializer(const EstimatorOptions& options, const EstimatorInput& input) {
  switch (options.init) {
    case InitMode::kGroundTruth:
      if (input.groundtruth.empty())
        throw InputError(
            "estimator.init: groundtruth initialization needs ground truth, and the input has none");
      return std::make_unique<GroundTruthInitializer>(input.groundtruth, options.groundtruth_init,
                                                      input.seed);
    case InitMode::kVins: {
      auto vins = std::make_unique<VinsInitializer>(options.vins, input.camera, input.gravity_mps2,
                                                    options.window.size + 1);
      if (!options.zero_velocity.static_init) return vins;
      return std::make_unique<StaticInitializer>(std::move(vins), StaticStartTests(options.zero_velocity),
                                                 input.camera.fx);
    }
  }
  throw InputError("estimator.init: unknown initialization mode");
}

}  // namespace vigil::estimator
