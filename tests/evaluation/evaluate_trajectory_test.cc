#include "evaluation/evaluate_trajectory.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/dataset.h"
#include "core/output.h"
#include "core/so3.h"

namespace vigil::evaluation {
namespace {

// The reference ellipse motion at 30 Hz for `seconds`.
Trajectory Ellipse(double seconds) {
  Trajectory traj;
  for (int k = 0; k < std::lround(seconds * 30); ++k) {
    const double t = k / 30.0, K = M_PI / 10;
    StampedPose p;
    p.t_ns = SToNs(t);
    p.p_W = Eigen::Vector3d(15 * std::cos(K * t) + 5, 20 * std::sin(K * t) + 5, std::sin(10 * K * t) + 5);
    p.q_WB = Eigen::Quaterniond(RotZ(K * t) * Eigen::AngleAxisd(0.2 * std::sin(t), Eigen::Vector3d::UnitY()) *
                                Eigen::AngleAxisd(0.1 * std::cos(t), Eigen::Vector3d::UnitX()));
    traj.push_back(p);
  }
  return traj;
}

TEST(EvaluateTrajectory, YawAndTranslationOffsetAlignsToZeroUnderPosYaw) {
  const Trajectory gt = Ellipse(20);
  Trajectory est = gt;
  const Eigen::Matrix3d R = RotZ(-2.0);
  for (auto& p : est) {
    p.p_W = R * p.p_W + Eigen::Vector3d(7, -1, 0.5);
    p.q_WB = Eigen::Quaterniond(R) * p.q_WB;
  }
  const TrajectoryEvaluation ev = EvaluateTrajectory(gt, est, EvaluationOptions{});
  EXPECT_EQ(ev.matched_poses, gt.size());
  EXPECT_DOUBLE_EQ(ev.coverage, 1.0);
  EXPECT_NEAR(ev.ate_trans_m.max, 0.0, 1e-9);
  EXPECT_NEAR(ev.ate_rot_deg.max, 0.0, 1e-5);
  EXPECT_NEAR(ev.gt_length_m, 119.0, 1.0);  // one loop is about 119 m (docs/references.md)
  ASSERT_EQ(ev.relative.size(), 5u);
  for (const auto& rel : ev.relative) {
    EXPECT_GT(rel.trans_m.n, 100) << rel.distance_m;
    EXPECT_NEAR(rel.trans_m.max, 0.0, 1e-9);
    EXPECT_NEAR(rel.yaw_deg.max, 0.0, 1e-6);
  }
  // The same offset is not removed without alignment, and a roll offset is not removed by posyaw.
  EvaluationOptions none;
  none.align = Alignment::kNone;
  EXPECT_GT(EvaluateTrajectory(gt, est, none).ate_trans_m.rmse, 1.0);
  Trajectory tilted = gt;
  for (auto& p : tilted) {
    p.p_W = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) * p.p_W;
    p.q_WB = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) * p.q_WB;
  }
  EXPECT_GT(EvaluateTrajectory(gt, tilted, EvaluationOptions{}).ate_trans_m.rmse, 0.1);
  EvaluationOptions se3;
  se3.align = Alignment::kSe3;
  EXPECT_NEAR(EvaluateTrajectory(gt, tilted, se3).ate_trans_m.max, 0.0, 1e-9);
}

TEST(EvaluateTrajectory, KnownAteOfAConstantOffsetWithoutAlignment) {
  const Trajectory gt = Ellipse(10);
  Trajectory est = gt;
  for (auto& p : est) p.p_W += Eigen::Vector3d(0.3, 0.4, 0.0);  // 0.5 m
  EvaluationOptions options;
  options.align = Alignment::kNone;
  const TrajectoryEvaluation ev = EvaluateTrajectory(gt, est, options);
  EXPECT_NEAR(ev.ate_trans_m.rmse, 0.5, 1e-12);
  EXPECT_NEAR(ev.ate_trans_m.std, 0.0, 1e-12);
  EXPECT_NEAR(ev.ate_rot_deg.max, 0.0, 1e-6);
}

TEST(EvaluateTrajectory, CoverageCountsCoveredGroundTruthPoses) {
  const Trajectory gt = Ellipse(20);
  Trajectory est;
  for (std::size_t k = gt.size() / 2; k < gt.size(); ++k) est.push_back(gt[k]);  // estimator started late
  const TrajectoryEvaluation half = EvaluateTrajectory(gt, est, EvaluationOptions{});
  EXPECT_DOUBLE_EQ(half.coverage, 0.5);
  EXPECT_NEAR(half.ate_trans_m.rmse, 0.0, 1e-9);

  Trajectory shifted = gt;  // 25 ms late: each pose matches the next ground-truth pose (8.3 ms away)
  for (auto& p : shifted) p.t_ns += 25'000'000;
  EXPECT_EQ(EvaluateTrajectory(gt, shifted, EvaluationOptions{}).matched_poses, gt.size() - 1);

  // Every third pose of the 30 Hz ground truth (an estimator solving 10 frames per second) covers all the
  // poses from its first to its last; with no gap allowed, only the matched third.
  Trajectory third;
  for (std::size_t k = 0; k < gt.size(); k += 3) third.push_back(gt[k]);
  const TrajectoryEvaluation ten_hz = EvaluateTrajectory(gt, third, EvaluationOptions{});
  EXPECT_EQ(ten_hz.matched_poses, third.size());
  EXPECT_EQ(ten_hz.covered_poses, 3 * (third.size() - 1) + 1);
  EvaluationOptions no_gap;
  no_gap.max_pose_gap_s = 0.0;
  EXPECT_EQ(EvaluateTrajectory(gt, third, no_gap).covered_poses, third.size());

  const TrajectoryEvaluation empty = EvaluateTrajectory(gt, {}, EvaluationOptions{});
  EXPECT_EQ(empty.matched_poses, 0u);
  EXPECT_EQ(empty.coverage, 0.0);
  EXPECT_EQ(empty.ate_trans_m.n, 0);
  const nlohmann::json j = EvaluationJson(empty);
  EXPECT_TRUE(j["ate"]["trans_m"]["rmse"].is_null());
  EXPECT_EQ(j["relative"].size(), 5u);
}

TEST(EvaluateTrajectory, JsonHasTheKeysOfFormatsMd) {
  const Trajectory gt = Ellipse(20);
  const nlohmann::json j = EvaluationJson(EvaluateTrajectory(gt, gt, EvaluationOptions{}));
  EXPECT_EQ(j["ate"]["align"], "posyaw");
  for (const char* key : {"trans_m", "rot_deg"})
    for (const char* stat : {"rmse", "mean", "median", "std", "min", "max", "n"})
      EXPECT_TRUE(j["ate"][key].contains(stat)) << key << " " << stat;
  ASSERT_EQ(j["relative"].size(), 5u);
  EXPECT_EQ(j["relative"][0]["distance_m"], 7.0);
  for (const char* key : {"trans_m", "yaw_deg", "rot_deg", "trans_perc"})
    EXPECT_TRUE(j["relative"][4][key].contains("rmse")) << key;
  EXPECT_EQ(j["coverage"], 1.0);
  EXPECT_NE(EvaluationTable(EvaluateTrajectory(gt, gt, EvaluationOptions{})).find("RE 35 m yaw [deg]"),
            std::string::npos);
}

}  // namespace
}  // namespace vigil::evaluation

namespace vigil::evaluation {
namespace {

TEST(EvaluateTrajectory, MatchesRpgTrajectoryEvaluationOnTheSameFiles) {
  const std::string data = std::string(VIGIL_SOURCE_DIR) + "/tests/evaluation/data/";
  const Trajectory gt = ReadTumTrajectory(data + "rpg_pair_gt.txt");
  const Trajectory est = ReadTumTrajectory(data + "rpg_pair_est.txt");
  const nlohmann::json reference = nlohmann::json::parse(ReadFile(data + "rpg_pair_reference.json"));
  const auto expect_stats = [](const nlohmann::json& ref, const ErrorStatistics& s, const std::string& what) {
    if (ref.is_null()) {
      EXPECT_EQ(s.n, 0) << what;
      return;
    }
    EXPECT_EQ(s.n, ref["n"].get<int64_t>()) << what;
    const std::pair<const char*, double> values[] = {{"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median},
                                                     {"std", s.std},   {"min", s.min},   {"max", s.max}};
    for (const auto& [key, value] : values) {
      const double r = ref[key].get<double>();
      EXPECT_NEAR(value, r, 1e-6 * std::abs(r) + 1e-9) << what << " " << key;
    }
  };
  for (const auto& [name, align] : AlignmentNames()) {
    EvaluationOptions options;
    options.align = align;
    const TrajectoryEvaluation ev = EvaluateTrajectory(gt, est, options);
    const nlohmann::json& ref = reference.at(name);
    expect_stats(ref["ate"]["trans_m"], ev.ate_trans_m, name + " ATE translation");
    expect_stats(ref["ate"]["rot_deg"], ev.ate_rot_deg, name + " ATE rotation");
    ASSERT_EQ(ev.relative.size(), ref["relative"].size());
    for (std::size_t i = 0; i < ev.relative.size(); ++i) {
      const std::string what = name + " RE " + std::to_string(ev.relative[i].distance_m);
      expect_stats(ref["relative"][i]["trans_m"], ev.relative[i].trans_m, what + " translation");
      expect_stats(ref["relative"][i]["yaw_deg"], ev.relative[i].yaw_deg, what + " yaw");
      expect_stats(ref["relative"][i]["rot_deg"], ev.relative[i].rot_deg, what + " rotation");
    }
  }
}

// A run's errors are no result when they rest on too little of it: one or two matched poses of a whole
// ground truth (one pose aligns exactly), or a yaw fitted to a centimetre of travel.
TEST(EvaluateTrajectory, TooLittleCoverageOrMotionIsInconclusive) {
  const Trajectory gt = Ellipse(20);
  const Trajectory two_poses(gt.begin(), gt.begin() + 2);
  const TrajectoryEvaluation few = EvaluateTrajectory(gt, two_poses, EvaluationOptions{});
  EXPECT_EQ(few.matched_poses, 2u);
  EXPECT_NE(few.inconclusive_reason.find("is below evaluation.min_coverage 25.0 %"), std::string::npos)
      << few.inconclusive_reason;
  EXPECT_FALSE(few.diverged);
  const Trajectory quarter(gt.begin(), gt.begin() + static_cast<long>(gt.size() / 4) + 1);
  EXPECT_EQ(EvaluateTrajectory(gt, quarter, EvaluationOptions{}).inconclusive_reason, "");
  const Trajectory less(gt.begin(), gt.begin() + static_cast<long>(gt.size() / 4) - 1);
  EXPECT_NE(EvaluateTrajectory(gt, less, EvaluationOptions{}).inconclusive_reason, "");
  EXPECT_EQ(EvaluateTrajectory(gt, gt, EvaluationOptions{}).inconclusive_reason, "");

  // Standing still (1 cm of jitter): the yaw of posyaw is arbitrary, so no ATE is computed ...
  Trajectory still_gt, still_est;
  for (int k = 0; k < 120; ++k) {
    StampedPose p;
    p.t_ns = SToNs(k / 30.0);
    p.p_W = Eigen::Vector3d(0.01 * std::sin(k), 0.005 * std::cos(k), 1.0);
    still_gt.push_back(p);
    p.q_WB = Eigen::Quaterniond(RotZ(0.001 * k));
    still_est.push_back(p);
  }
  const TrajectoryEvaluation still = EvaluateTrajectory(still_gt, still_est, EvaluationOptions{});
  EXPECT_FALSE(still.alignment_defined);
  EXPECT_LT(still.alignment_extent_m, 0.02);
  EXPECT_NE(still.inconclusive_reason.find("too little motion to define the posyaw alignment"),
            std::string::npos)
      << still.inconclusive_reason;
  EXPECT_EQ(still.ate_trans_m.n, 0);
  EXPECT_EQ(still.ate_rot_deg.n, 0);
  const nlohmann::json json = EvaluationJson(still);
  EXPECT_EQ(json["ate"]["alignment_defined"], false);
  EXPECT_TRUE(json["ate"]["rot_deg"]["rmse"].is_null());
  EXPECT_NE(EvaluationTable(still).find("inconclusive: the matched ground truth spans"), std::string::npos);
  // ... while without alignment the same run has its errors, and a vertical motion does not define a yaw.
  EvaluationOptions none;
  none.align = Alignment::kNone;
  const TrajectoryEvaluation unaligned = EvaluateTrajectory(still_gt, still_est, none);
  EXPECT_TRUE(unaligned.alignment_defined);
  EXPECT_EQ(unaligned.inconclusive_reason, "");
  EXPECT_NEAR(unaligned.ate_rot_deg.max, 0.001 * 119 * 180 / M_PI, 1e-6);
  Trajectory lift = still_gt;
  for (std::size_t k = 0; k < lift.size(); ++k) lift[k].p_W.z() = 0.02 * static_cast<double>(k);
  EXPECT_FALSE(EvaluateTrajectory(lift, lift, EvaluationOptions{}).alignment_defined);
  EvaluationOptions se3;
  se3.align = Alignment::kSe3;
  EXPECT_TRUE(EvaluateTrajectory(lift, lift, se3).alignment_defined);
}

}  // namespace
}  // namespace vigil::evaluation
