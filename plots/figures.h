// The six figures (docs/sweeps.md), built from plain data (the loaders in render.h fill it from directories).
//
//  1. Scenario: trajectory and landmarks in X-Y, X-Z, Y-Z and a 3-D perspective view.
//  2. Glitches: one IMU axis over time with and without injected glitches, one panel per glitch setting.
//  3. Trajectories per glitch setting: ground truth and each method's aligned estimate, top and side view.
//  4. Relative translation and yaw error vs distance travelled: box plots per method.
//  5. Detection: an IMU excerpt with flagged samples shaded and the mitigated signal overlaid.
//  6. Sweep summary: ATE per glitch setting for each method, with the spread over seeds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "plots/axes.h"
#include "plots/figure.h"

namespace vigil::plots {

struct ScenarioData {
  std::string title;
  std::vector<Eigen::Vector3d> path_W;  // body positions
  std::vector<Eigen::Vector3d> landmarks_W;
};
Figure ScenarioFigure(const ScenarioData& data);

struct ImuTrace {
  std::string label;      // panel title (e.g. the glitch setting)
  std::string axis_name;  // e.g. "a_z"
  std::string unit;       // e.g. "m/s²"
  std::vector<double> t_s, clean, measured;
};
Figure GlitchFigure(const std::vector<ImuTrace>& panels);

struct MethodTrajectory {
  std::string method;
  std::vector<Eigen::Vector3d> p_W;
};
struct TrajectoryPanel {
  std::string label;
  std::vector<Eigen::Vector3d> groundtruth_W;
  std::vector<MethodTrajectory> estimates;
};
Figure TrajectoryFigure(const std::vector<TrajectoryPanel>& rows);

// One box per (method, distance).
struct RelativeErrorBoxes {
  std::string method;
  std::vector<double> distances_m;
  std::vector<BoxStats> trans_m, yaw_deg;  // one per distance
};
struct RelativeErrorRow {
  std::string label;
  std::vector<RelativeErrorBoxes> methods;
};
// `note` says what the boxes summarize (printed under the title).
Figure RelativeErrorFigure(const std::vector<RelativeErrorRow>& rows, const std::string& note);

struct DetectionTrace {
  std::string detector;   // method name
  std::string axis_name;  // e.g. "a_z"
  std::string unit;
  std::vector<double> t_s, raw, mitigated, clean;  // clean may be empty
  std::vector<uint8_t> flagged;                    // one per sample
  double excerpt_t0_s = 0.0, excerpt_t1_s = 0.0;   // the zoomed window
};
Figure DetectionFigure(const DetectionTrace& trace);

struct SummaryCell {
  std::string method;
  int setting = 0;                               // index into the labels
  std::vector<double> ate_trans_m, ate_rot_deg;  // one per seed (successful runs)
  int failed = 0;
};
Figure SummaryFigure(const std::vector<std::string>& setting_labels, const std::vector<std::string>& methods,
                     const std::vector<SummaryCell>& cells);

}  // namespace vigil::plots
