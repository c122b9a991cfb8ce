// Reading a recorded ground-truth trajectory: timed poses (and velocities where the recording has them).
//
// Accepted inputs (ReadRecordedPoses):
// - EuRoC state_groundtruth_estimate0/data.csv (or vigil's groundtruth.csv, the same layout): a '#' header,
//   then comma-separated rows of 17 or more columns: timestamp [ns], p_W (x y z) [m], q_WB (w x y z),
//   v_W (x y z) [m/s], biases (ignored), further columns ignored;
// - the folder holding that file's mav0/ folder, or mav0/ itself;
// - a TUM / rpg text trajectory: whitespace-separated "timestamp [s] tx ty tz qx qy qz qw", '#' comments.
// Rows must have finite values, strictly increasing timestamps and unit quaternions (core/pose_checks.h;
// renormalized); at least 2 rows; consecutive poses must not jump (more than kMaxRecordedSpeed_mps, or more
// than kMaxPoseRotationStep_rad between two rows, core/pose_checks.h), and no gap between two rows may exceed
// 1 s (kMaxGroundTruthGap_ns, core/ground_truth_gap.h). Errors: InputError "file:line: reason".
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vigil::sim {

struct TimedPose {
  TimedPose() = default;
  TimedPose(int64_t t, const Eigen::Vector3d& p, const Eigen::Quaterniond& q,
            std::optional<Eigen::Vector3d> v = std::nullopt)
      : t_ns(t), p_W(p), q_WB(q), v_W(std::move(v)) {}

  int64_t t_ns = 0;  // absolute time of the recording
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  std::optional<Eigen::Vector3d> v_W;  // recorded velocity [m/s] (EuRoC ground truth), absent for TUM
};

// A recorded pose faster than this between two rows is a jump of the recording, not a motion.
inline constexpr double kMaxRecordedSpeed_mps = 100.0;

std::vector<TimedPose> ReadRecordedPoses(const std::filesystem::path& path);

}  // namespace vigil::sim
