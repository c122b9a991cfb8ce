// Relative errors over sub-trajectories of a given length (rpg_trajectory_evaluation's odometry error).
//
// Distances travelled come from the matched ground-truth positions (cumulative sum of the steps, 0 at the
// first pose). For every start pose i, the end pose j >= i is the one whose distance from i is closest to L
// (the first such j on a tie); the pair counts when that difference is below max_difference_m (rpg: 0.2 L).
// Fewer than two such pairs give no sample. For a pair:
//   T_c = T_est,i^-1 T_est,j (its translation multiplied by the alignment scale), T_m = T_gt,i^-1 T_gt,j,
//   E = T_m^-1 T_c, expressed with the orientation of the estimate at j: E_W = (R_est,j E_R R_est,j^T,
//   R_est,j E_t). translation [m] = |E_t|; translation [%] = 100 |E_t| / L; yaw [deg] = |atan2(E_W,10,
//   E_W,00)| (ZYX yaw); rotation [deg] = angle of E_R.
// The estimate is used as estimated (relative motions do not depend on the alignment, except for its scale).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "evaluation/statistics.h"

namespace vigil::evaluation {

// Distance travelled from the first position to each position.
std::vector<double> DistanceFromStart(const std::vector<Eigen::Vector3d>& p);

// The (start, end) index pairs of sub-trajectories of length `distance_m` (see above); `distances` must be
// non-decreasing.
std::vector<std::pair<std::size_t, std::size_t>> SubTrajectoryPairs(const std::vector<double>& distances,
                                                                    double distance_m,
                                                                    double max_difference_m);

struct RelativeErrors {
  double distance_m = 0.0;
  std::vector<double> trans_m, trans_perc, yaw_deg, rot_deg;  // one entry per sub-trajectory
};

// `T_W_est` and `T_W_gt` are matched body poses (same length, else std::invalid_argument); `scale` multiplies
// the estimate's relative translations (1 unless the alignment is sim3); max_difference_m < 0 means 0.2
// distance_m.
RelativeErrors ComputeRelativeErrors(const std::vector<Eigen::Isometry3d>& T_W_est,
                                     const std::vector<Eigen::Isometry3d>& T_W_gt, double distance_m,
                                     double scale = 1.0, double max_difference_m = -1.0);

}  // namespace vigil::evaluation
