// Initialization from ground truth (`estimator.init: groundtruth`): each window frame's state is the ground
// truth interpolated at its time, optionally perturbed by Gaussian noise drawn from Rng(seed,
// "init_perturbation"). Succeeds on the first call whose frames all lie inside the ground truth; cannot
// re-initialize after a failure.
#pragma once

#include <cstdint>
#include <vector>

#include "core/random.h"
#include "estimator/estimator_options.h"
#include "estimator/initializer.h"

namespace vigil::estimator {

class GroundTruthInitializer : public Initializer {
 public:
  GroundTruthInitializer(std::vector<NavState> groundtruth, const GroundTruthInitOptions& options,
                         uint64_t seed);

  bool TryInitialize(const std::vector<InitFrame>& window, InitResult* result) override;
  bool CanReinitialize() const override { return false; }

 private:
  std::vector<NavState> groundtruth_;
  GroundTruthInitOptions options_;
  Rng rng_;
};

}  // namespace vigil::estimator
