#include "estimator/ground_truth_initializer.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/so3.h"
#include "estimator/make_initializer.h"

namespace vigil::estimator {
namespace {

std::vector<NavState> LinearMotion() {
  std::vector<NavState> gt;
  for (int k = 0; k <= 10; ++k) {
    NavState s;
    s.t_ns = k * 100'000'000LL;
    s.p_W = Eigen::Vector3d(k * 0.1, 0.0, 1.0);
    s.v_W = Eigen::Vector3d(1.0, 0.0, 0.0);
    s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * k, Eigen::Vector3d::UnitZ()));
    gt.push_back(s);
  }
  return gt;
}

std::vector<InitFrame> Frames(std::initializer_list<int64_t> times_ns) {
  std::vector<InitFrame> frames;
  for (const int64_t t : times_ns) frames.push_back(InitFrame{t, {}, std::nullopt});
  return frames;
}

TEST(GroundTruthInitializerTest, InterpolatesGroundTruthAtFrameTimes) {
  GroundTruthInitializer init(LinearMotion(), {}, 1);
  InitResult result;
  ASSERT_TRUE(init.TryInitialize(Frames({0, 150'000'000, 1'000'000'000}), &result));
  ASSERT_EQ(result.states.size(), 3u);
  EXPECT_EQ(result.states[1].t_ns, 150'000'000);
  EXPECT_LT((result.states[1].p_W - Eigen::Vector3d(0.15, 0.0, 1.0)).norm(), 1e-12);
  EXPECT_NEAR(YawOf(result.states[1].q_WB.toRotationMatrix()), 0.15, 1e-12);
  EXPECT_FALSE(init.CanReinitialize());
}

TEST(GroundTruthInitializerTest, FailsOutsideTheGroundTruth) {
  GroundTruthInitializer init(LinearMotion(), {}, 1);
  InitResult result;
  EXPECT_FALSE(init.TryInitialize(Frames({0, 2'000'000'000}), &result));
  EXPECT_FALSE(result.failure_reason.empty());
  EXPECT_TRUE(result.states.empty());
}

TEST(GroundTruthInitializerTest, PerturbationIsSeededAndOfTheConfiguredSize) {
  GroundTruthInitOptions options;
  options.position_std_m = 0.5;
  options.rotation_std_deg = 2.0;
  InitResult a, b, c;
  std::vector<InitFrame> frames;
  for (int k = 0; k < 200; ++k) frames.push_back(InitFrame{k * 5'000'000LL, {}, std::nullopt});
  ASSERT_TRUE(GroundTruthInitializer(LinearMotion(), options, 3).TryInitialize(frames, &a));
  ASSERT_TRUE(GroundTruthInitializer(LinearMotion(), options, 3).TryInitialize(frames, &b));
  ASSERT_TRUE(GroundTruthInitializer(LinearMotion(), options, 4).TryInitialize(frames, &c));
  GroundTruthInitializer exact(LinearMotion(), {}, 3);
  InitResult truth;
  ASSERT_TRUE(exact.TryInitialize(frames, &truth));
  double sum_sq_m = 0.0, sum_sq_rad = 0.0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(a.states[i].p_W, b.states[i].p_W);
    EXPECT_NE(a.states[i].p_W, c.states[i].p_W);
    sum_sq_m += (a.states[i].p_W - truth.states[i].p_W).squaredNorm();
    sum_sq_rad += LogQ(truth.states[i].q_WB.conjugate() * a.states[i].q_WB).squaredNorm();
    EXPECT_EQ(a.states[i].v_W, truth.states[i].v_W);  // velocity std 0
  }
  const double std_m = std::sqrt(sum_sq_m / (3.0 * frames.size()));
  const double std_deg = std::sqrt(sum_sq_rad / (3.0 * frames.size())) * 180.0 / M_PI;
  EXPECT_NEAR(std_m, 0.5, 0.08);
  EXPECT_NEAR(std_deg, 2.0, 0.3);
}

TEST(MakeInitializerTest, GroundTruthInitNeedsGroundTruth) {
  EstimatorOptions options;
  EstimatorInput input;
  EXPECT_THROW(MakeInitializer(options, input), InputError);
  input.groundtruth = LinearMotion();
  EXPECT_NE(MakeInitializer(options, input), nullptr);
}

}  // namespace
}  // namespace vigil::estimator
