// The failure path of an initializer that can re-initialize: reset the window, count the reset, initialize
// again and continue.
#include "estimator/estimator.h"

#include <map>
#include <memory>

#include <gtest/gtest.h>

#include "estimator/ground_truth_initializer.h"
#include "tests/estimator/sim_run.h"

namespace vigil::estimator {
namespace {

// Ground truth that claims it may re-initialize (as the visual-inertial initializer does).
class ReinitializingGroundTruth : public GroundTruthInitializer {
 public:
  using GroundTruthInitializer::GroundTruthInitializer;
  bool CanReinitialize() const override { return true; }
};

TEST(EstimatorResetTest, FailureResetsAndReinitializes) {
  auto [data, input] = testing::SimulatePaperRun(3.0, 5);
  for (ImuSample& s : input.imu)
    if (s.t_ns > 1'000'000'000 && s.t_ns < 1'200'000'000) s.a_B.z() += 1000.0;
  Estimator estimator(
      EstimatorOptions{}, input.camera, input.imu_noise, input.gravity_mps2, 200.0,
      std::make_unique<ReinitializingGroundTruth>(input.groundtruth, GroundTruthInitOptions{}, 5));
  int resets = 0, tracking_after_reset = 0;
  for (const CameraFrame& frame : input.frames) {
    std::map<int, Eigen::Vector2d> features_n;
    for (const FeatureObservation& obs : frame.features)
      features_n[obs.id] = input.camera.Normalize(obs.uv_px);
    const FrameStatus status = estimator.AddFrame(frame.t_ns, features_n, input.imu);
    ASSERT_NE(status, FrameStatus::kFailed);
    if (status == FrameStatus::kReset) ++resets;
    if (status == FrameStatus::kTracking && resets > 0) {
      ++tracking_after_reset;
      EXPECT_TRUE(estimator.newest_state().p_W.allFinite());
    }
  }
  EXPECT_GE(resets, 1);
  EXPECT_EQ(estimator.resets(), resets);
  EXPECT_GT(tracking_after_reset, 10);
  // After the glitch the re-initialized estimate is accurate again.
  NavState truth;
  ASSERT_TRUE(InterpolateNavState(data.groundtruth, estimator.newest_state().t_ns, &truth));
  EXPECT_LT((estimator.newest_state().p_W - truth.p_W).norm(), 0.3);
}

}  // namespace
}  // namespace vigil::estimator
