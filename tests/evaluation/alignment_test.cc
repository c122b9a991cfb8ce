#include "evaluation/alignment.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/random.h"
#include "core/so3.h"

namespace vigil::evaluation {
namespace {

std::vector<Eigen::Vector3d> RandomPoints(int n, uint64_t seed) {
  Rng rng(seed, "alignment_test");
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < n; ++k) p.emplace_back(rng.Uniform(-10, 10), rng.Uniform(-10, 10), rng.Uniform(-2, 2));
  return p;
}

std::vector<Eigen::Vector3d> Transform(const std::vector<Eigen::Vector3d>& p, double s,
                                       const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& x : p) out.push_back(s * (R * x) + t);
  return out;
}

double Cost(const SimilarityTransform& T, const std::vector<Eigen::Vector3d>& est,
            const std::vector<Eigen::Vector3d>& gt) {
  double c = 0;
  for (std::size_t k = 0; k < est.size(); ++k) c += (gt[k] - T.Apply(est[k])).squaredNorm();
  return c;
}

TEST(Alignment, PosYawRecoversYawAndTranslation) {
  const auto est = RandomPoints(50, 1);
  const Eigen::Matrix3d R = RotZ(2.5);  // beyond pi/2: the closed form covers every quadrant
  const Eigen::Vector3d t(3, -4, 1.5);
  const auto gt = Transform(est, 1.0, R, t);
  const SimilarityTransform T = AlignPositions(est, gt, Alignment::kPosYaw);
  EXPECT_NEAR((T.R - R).norm(), 0.0, 1e-12);
  EXPECT_NEAR((T.t - t).norm(), 0.0, 1e-12);
  EXPECT_EQ(T.scale, 1.0);
  EXPECT_NEAR(Cost(T, est, gt), 0.0, 1e-18);
}

TEST(Alignment, Se3AndSim3RecoverAFullRotationAndScale) {
  const auto est = RandomPoints(40, 2);
  const Eigen::Matrix3d R = ExpQ(Eigen::Vector3d(0.3, -0.7, 1.9)).toRotationMatrix();
  const Eigen::Vector3d t(-1, 2, 5);
  const SimilarityTransform se3 = AlignPositions(est, Transform(est, 1.0, R, t), Alignment::kSe3);
  EXPECT_NEAR((se3.R - R).norm(), 0.0, 1e-10);
  EXPECT_NEAR((se3.t - t).norm(), 0.0, 1e-10);
  const SimilarityTransform sim3 = AlignPositions(est, Transform(est, 2.5, R, t), Alignment::kSim3);
  EXPECT_NEAR(sim3.scale, 2.5, 1e-10);
  EXPECT_NEAR((sim3.R - R).norm(), 0.0, 1e-10);
  EXPECT_NEAR((sim3.t - t).norm(), 0.0, 1e-9);
  // se3 and posyaw keep the scale at 1 even when the data is scaled.
  EXPECT_EQ(AlignPositions(est, Transform(est, 2.5, R, t), Alignment::kSe3).scale, 1.0);
  const SimilarityTransform none = AlignPositions(est, Transform(est, 1.0, R, t), Alignment::kNone);
  EXPECT_TRUE(none.R.isIdentity() && none.t.isZero() && none.scale == 1.0);
}

TEST(Alignment, PosYawIsTheBruteForceOptimumOnNoisyData) {
  const auto est = RandomPoints(30, 3);
  auto gt = Transform(est, 1.0, RotZ(-1.2) * ExpQ(Eigen::Vector3d(0.05, -0.03, 0)).toRotationMatrix(),
                      Eigen::Vector3d(1, 1, 1));
  Rng rng(4, "noise");
  for (auto& p : gt) p += Eigen::Vector3d(rng.Normal(), rng.Normal(), rng.Normal()) * 0.3;
  const SimilarityTransform best = AlignPositions(est, gt, Alignment::kPosYaw);
  const double best_cost = Cost(best, est, gt);
  // For each yaw the optimal translation maps the centroids onto each other.
  Eigen::Vector3d mu_est = Eigen::Vector3d::Zero(), mu_gt = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < est.size(); ++k) mu_est += est[k] / est.size(), mu_gt += gt[k] / gt.size();
  for (int i = 0; i < 3600; ++i) {
    SimilarityTransform T;
    T.R = RotZ(-M_PI + i * (2 * M_PI / 3600));
    T.t = mu_gt - T.R * mu_est;
    EXPECT_GE(Cost(T, est, gt), best_cost - 1e-9) << i;
  }
  // And a full rotation can only do better than yaw alone.
  EXPECT_LE(Cost(AlignPositions(est, gt, Alignment::kSe3), est, gt), best_cost + 1e-9);
}

TEST(Alignment, Se3IsALocalOptimum) {
  const auto est = RandomPoints(30, 5);
  auto gt = Transform(est, 1.0, ExpQ(Eigen::Vector3d(1, 2, 3)).toRotationMatrix(), Eigen::Vector3d(1, 0, 0));
  Rng rng(6, "noise");
  for (auto& p : gt) p += Eigen::Vector3d(rng.Normal(), rng.Normal(), rng.Normal()) * 0.5;
  const SimilarityTransform best = AlignPositions(est, gt, Alignment::kSe3);
  const double best_cost = Cost(best, est, gt);
  for (int i = 0; i < 200; ++i) {
    SimilarityTransform T = best;
    T.R = ExpQ(Eigen::Vector3d(rng.Normal(), rng.Normal(), rng.Normal()) * 0.01).toRotationMatrix() * best.R;
    T.t += Eigen::Vector3d(rng.Normal(), rng.Normal(), rng.Normal()) * 0.01;
    EXPECT_GE(Cost(T, est, gt), best_cost);
  }
}

TEST(Alignment, SinglePairAndBadInput) {
  const SimilarityTransform T =
      AlignPositions({Eigen::Vector3d(1, 2, 3)}, {Eigen::Vector3d(2, 2, 2)}, Alignment::kPosYaw);
  EXPECT_TRUE(T.R.isIdentity());
  EXPECT_EQ(T.t, Eigen::Vector3d(1, 0, -1));
  EXPECT_THROW(AlignPositions({}, {}, Alignment::kSe3), std::invalid_argument);
  EXPECT_THROW(AlignPositions({Eigen::Vector3d::Zero()}, {}, Alignment::kSe3), std::invalid_argument);
}

}  // namespace
}  // namespace vigil::evaluation
