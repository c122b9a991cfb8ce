#include "estimator/ground_truth_initializer.h"

#include <cmath>
#include <utility>

#include "core/format.h"
#include "core/interpolation.h"
#include "core/so3.h"

namespace vigil::estimator {

GroundTruthInitializer::GroundTruthInitializer(std::vector<NavState> groundtruth,
                                               const GroundTruthInitOptions& options, uint64_t seed)
    : groundtruth_(std::move(groundtruth)), options_(options), rng_(seed, "init_perturbation") {}

bool GroundTruthInitializer::TryInitialize(const std::vector<InitFrame>& window, InitResult* result) {
  result->states.clear();
  result->landmarks_W.clear();
  result->failure_reason.clear();
  if (window.empty()) {
    result->failure_reason = "empty window";
    return false;
  }
  const auto normal3 = [this](double std) { return Eigen::Vector3d(std * rng_.NormalVector3()); };
  const double rotation_std_rad = options_.rotation_std_deg * M_PI / 180.0;
  for (const InitFrame& frame : window) {
    NavState state;
    if (!InterpolateNavState(groundtruth_, frame.t_ns, &state)) {
      result->states.clear();
      result->failure_reason = "no ground truth at t = " + FormatFixed(NsToS(frame.t_ns), 3) + " s";
      return false;
    }
    state.p_W += normal3(options_.position_std_m);
    state.q_WB = (state.q_WB * ExpQ(normal3(rotation_std_rad))).normalized();
    state.v_W += normal3(options_.velocity_std_mps);
    result->states.push_back(state);
  }
  return true;
}

}  // namespace vigil::estimator
