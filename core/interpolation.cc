#include "core/interpolation.h"

#include <algorithm>

namespace vigil {

bool InterpolateNavState(const std::vector<NavState>& states, int64_t t_ns, NavState* out) {
  if (states.empty() || t_ns < states.front().t_ns || t_ns > states.back().t_ns) return false;
  const auto hi = std::lower_bound(states.begin(), states.end(), t_ns,
                                   [](const NavState& s, int64_t t) { return s.t_ns < t; });
  if (hi->t_ns == t_ns || hi == states.begin()) {
    *out = *hi;
    out->t_ns = t_ns;
    return true;
  }
  const NavState& a = *(hi - 1);
  const NavState& b = *hi;
  const double s = static_cast<double>(t_ns - a.t_ns) / static_cast<double>(b.t_ns - a.t_ns);
  out->t_ns = t_ns;
  out->p_W = (1.0 - s) * a.p_W + s * b.p_W;
  out->v_W = (1.0 - s) * a.v_W + s * b.v_W;
  out->b_a = (1.0 - s) * a.b_a + s * b.b_a;
  out->b_g = (1.0 - s) * a.b_g + s * b.b_g;
  out->q_WB = a.q_WB.slerp(s, b.q_WB).normalized();
  return true;
}

}  // namespace vigil
