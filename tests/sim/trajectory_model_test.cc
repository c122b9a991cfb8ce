#include "sim/trajectory_model.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/so3.h"
#include "sim/ellipse_trajectory.h"

namespace vigil::sim {
namespace {

// Checks the model's exact derivatives against central differences of the model itself (the test may use
// finite differences; the models may not). Errors of central differences are O(h^2): with h = 1e-4 s and
// derivatives of order 1..100 the truncation error is below 1e-6 and the rounding error about 1e-16 / h^2.
void ExpectDerivativesConsistent(const TrajectoryModel& model, double t_end, double tol) {
  const double h = 1e-4;
  for (double t = h; t < t_end - h; t += 0.0137 * t_end) {
    const TrajectoryState x = model.StateAt(t), xm = model.StateAt(t - h), xp = model.StateAt(t + h);
    EXPECT_LT((x.v_W - (xp.p_W - xm.p_W) / (2 * h)).norm(), tol) << "velocity at t = " << t;
    EXPECT_LT((x.a_W - (xp.v_W - xm.v_W) / (2 * h)).norm(), tol) << "acceleration at t = " << t;
    // Body rate: R(t + h) = R(t - h) Exp(w_B 2h) to second order in h.
    const Eigen::Vector3d w_fd = LogQ(xm.q_WB.conjugate() * xp.q_WB) / (2 * h);
    EXPECT_LT((x.w_B - w_fd).norm(), tol) << "body rate at t = " << t;
    EXPECT_NEAR(x.q_WB.norm(), 1.0, 1e-12);
  }
}

TEST(EllipseTrajectory, MatchesTheReferenceAtTimeZero) {
  const EllipseTrajectory e;
  const TrajectoryState x = e.StateAt(0.0);
  constexpr double K = EllipseTrajectory::kK;
  EXPECT_LT((x.p_W - Eigen::Vector3d(20, 5, 5)).norm(), 1e-12);
  EXPECT_LT((x.v_W - Eigen::Vector3d(0, 20 * K, 10 * K)).norm(), 1e-12);
  EXPECT_LT((x.a_W - Eigen::Vector3d(-15 * K * K, 0, 0)).norm(), 1e-12);
  // roll = 0.1, pitch = yaw = 0 at t = 0; Euler rates (0, 0.2, K) -> w_B = E (0, 0.2, K).
  EXPECT_NEAR(AngleOf(x.q_WB), 0.1, 1e-12);
  const Eigen::Vector3d w(0.0, std::cos(0.1) * 0.2 + std::sin(0.1) * K,
                          -std::sin(0.1) * 0.2 + std::cos(0.1) * K);
  EXPECT_LT((x.w_B - w).norm(), 1e-12);
  // One loop every 20 s.
  EXPECT_LT((e.StateAt(20.0).p_W - x.p_W).norm(), 1e-9);
}

TEST(EllipseTrajectory, DerivativesAreExact) { ExpectDerivativesConsistent(EllipseTrajectory(), 20.0, 1e-6); }

}  // namespace
}  // namespace vigil::sim
