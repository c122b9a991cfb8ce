// Interpolation of a time-ordered state sequence (e.g. ground truth at IMU rate) at arbitrary times.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"

namespace vigil {

// State at t_ns: positions, velocities and biases linearly, orientation by slerp between the two neighbours.
// `states` must be sorted by t_ns. Returns false when t_ns lies outside [first, last].
bool InterpolateNavState(const std::vector<NavState>& states, int64_t t_ns, NavState* out);

}  // namespace vigil
