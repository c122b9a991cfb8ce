#include "plots/figure_data.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <string_view>

#include "evaluation/metrics_access.h"
#include "plots/axes.h"
#include "plots/trajectory_alignment.h"

namespace vigil::plots {
namespace {

const char* AxisSymbol(ImuAxis axis) {
  static const char* kNames[] = {"ω_x", "ω_y", "ω_z", "a_x", "a_y", "a_z"};
  return kNames[static_cast<int>(axis)];
}
const char* AxisUnit(ImuAxis axis) { return static_cast<int>(axis) < 3 ? "rad/s" : "m/s²"; }

std::vector<Eigen::Vector3d> Positions(const Trajectory& trajectory) {
  std::vector<Eigen::Vector3d> p;
  p.reserve(trajectory.size());
  for (const StampedPose& pose : trajectory) p.push_back(pose.p_W);
  return p;
}

// The number at `path` in a metrics document when it is there and finite.
bool Stat(const nlohmann::json& metrics, std::initializer_list<std::string_view> path, double* value) {
  *value = evaluation::MetricNumber(metrics, path);
  return std::isfinite(*value);
}

}  // namespace

ScenarioData ScenarioDataOf(const Dataset& dataset, const std::string& title) {
  ScenarioData data;
  data.title = title;
  for (const NavState& s : dataset.groundtruth) data.path_W.push_back(s.p_W);
  for (const Landmark& l : dataset.landmarks) data.landmarks_W.push_back(l.p_W);
  return data;
}

ScenarioData ScenarioDataOf(const Trajectory& groundtruth, const std::vector<Landmark>& landmarks,
                            const std::string& title) {
  ScenarioData data;
  data.title = title;
  data.path_W = Positions(groundtruth);
  for (const Landmark& l : landmarks) data.landmarks_W.push_back(l.p_W);
  return data;
}

ImuAxis GlitchedAxis(const experiments::RunConfig& config) {
  return config.sim.glitch.axes.empty() ? ImuAxis::kAz : config.sim.glitch.axes.front();
}

ImuTrace ImuTraceOf(const Dataset& dataset, ImuAxis axis, const std::string& label) {
  ImuTrace trace;
  trace.label = label;
  trace.axis_name = AxisSymbol(axis);
  trace.unit = AxisUnit(axis);
  const ImuStream& clean = dataset.imu_clean.size() == dataset.imu.size() ? dataset.imu_clean : dataset.imu;
  const int a = static_cast<int>(axis);
  for (std::size_t i = 0; i < dataset.imu.size(); ++i) {
    trace.t_s.push_back(NsToS(dataset.imu[i].t_ns - dataset.imu.front().t_ns));
    trace.measured.push_back(dataset.imu[i].axis(a));
    trace.clean.push_back(clean[i].axis(a));
  }
  return trace;
}

ImuTrace ImuTraceOf(const experiments::ImuAxisRecord& record, const std::string& label) {
  ImuTrace trace;
  trace.label = label;
  trace.axis_name = AxisSymbol(record.axis);
  trace.unit = AxisUnit(record.axis);
  for (std::size_t i = 0; i < record.t_ns.size(); ++i)
    trace.t_s.push_back(NsToS(record.t_ns[i] - record.t_ns.front()));
  trace.measured = record.raw;
  trace.clean = record.clean.size() == record.raw.size() ? record.clean : record.raw;
  return trace;
}

TrajectoryPanel TrajectoryPanelOf(const std::string& label, const std::vector<const RunData*>& runs) {
  TrajectoryPanel panel;
  panel.label = label;
  for (const RunData* run : runs) {
    if (panel.groundtruth_W.empty()) panel.groundtruth_W = Positions(run->groundtruth);
    if (run->estimate.empty() || run->groundtruth.empty()) continue;
    panel.estimates.push_back({run->method, Positions(AlignForDisplay(run->estimate, run->groundtruth,
                                                                      run->config.evaluation.align))});
  }
  return panel;
}

RelativeErrorRow RelativeErrorRowOfRun(const std::string& label, const RunData& run) {
  RelativeErrorRow row;
  row.label = label;
  if (!run.metrics.is_object() || !run.metrics.contains("relative") || !run.metrics["relative"].is_array()) {
    return row;
  }
  RelativeErrorBoxes boxes;
  boxes.method = run.method;
  for (const nlohmann::json& entry : run.metrics["relative"]) {
    double d = 0.0;
    if (!Stat(entry, {"distance_m"}, &d)) continue;
    BoxStats stats[2];
    bool ok = true;
    const char* keys[2] = {"trans_m", "yaw_deg"};
    for (int k = 0; k < 2; ++k) {
      double mn, mx, mean, sd, median;
      if (!Stat(entry, {keys[k], "min"}, &mn) || !Stat(entry, {keys[k], "max"}, &mx) ||
          !Stat(entry, {keys[k], "mean"}, &mean) || !Stat(entry, {keys[k], "std"}, &sd) ||
          !Stat(entry, {keys[k], "median"}, &median)) {
        ok = false;
        break;
      }
      stats[k] = {mn, std::max(mn, mean - sd), median, std::min(mx, mean + sd), mx};
    }
    if (!ok) continue;
    boxes.distances_m.push_back(d);
    boxes.trans_m.push_back(stats[0]);
    boxes.yaw_deg.push_back(stats[1]);
  }
  if (!boxes.distances_m.empty()) row.methods.push_back(boxes);
  return row;
}

RelativeErrorRow RelativeErrorRowOfRuns(const std::string& label, const std::vector<const RunData*>& runs) {
  RelativeErrorRow row;
  row.label = label;
  // method -> distance -> per-run means
  std::map<std::string, std::map<double, std::pair<std::vector<double>, std::vector<double>>>> values;
  for (const RunData* run : runs) {
    if (!run->ok() || !run->metrics.contains("relative") || !run->metrics["relative"].is_array()) continue;
    for (const nlohmann::json& entry : run->metrics["relative"]) {
      double d, trans, yaw;
      if (!Stat(entry, {"distance_m"}, &d) || !Stat(entry, {"trans_m", "mean"}, &trans) ||
          !Stat(entry, {"yaw_deg", "mean"}, &yaw)) {
        continue;
      }
      auto& cell = values[run->method][d];
      cell.first.push_back(trans);
      cell.second.push_back(yaw);
    }
  }
  std::vector<std::string> methods;
  for (const auto& [method, unused] : values) methods.push_back(method);
  std::sort(methods.begin(), methods.end(), MethodBefore);
  for (const std::string& method : methods) {
    RelativeErrorBoxes boxes;
    boxes.method = method;
    for (const auto& [d, cell] : values[method]) {
      boxes.distances_m.push_back(d);
      boxes.trans_m.push_back(BoxStatsOf(cell.first));
      boxes.yaw_deg.push_back(BoxStatsOf(cell.second));
    }
    row.methods.push_back(boxes);
  }
  return row;
}

DetectionTrace DetectionTraceOf(const RunData& run, const experiments::ImuAxisRecord& record,
                                double excerpt_s) {
  DetectionTrace trace;
  trace.detector = run.method;
  trace.axis_name = AxisSymbol(record.axis);
  trace.unit = AxisUnit(record.axis);
  for (std::size_t i = 0; i < record.t_ns.size(); ++i)
    trace.t_s.push_back(NsToS(record.t_ns[i] - record.t_ns.front()));
  trace.raw = record.raw;
  trace.mitigated = record.mitigated;
  if (record.clean.size() == record.raw.size()) trace.clean = record.clean;
  trace.flagged = record.flagged;
  // The excerpt: the window with the most flagged samples (the earliest such window).
  const std::size_t n = trace.t_s.size();
  std::size_t best_start = 0, best_count = 0, count = 0, end = 0;
  for (std::size_t start = 0; start < n; ++start) {
    while (end < n && trace.t_s[end] < trace.t_s[start] + excerpt_s) count += trace.flagged[end++];
    if (count > best_count) {
      best_count = count;
      best_start = start;
    }
    count -= trace.flagged[start];
  }
  if (n > 0) {
    // Centre the flagged samples of the chosen window in the excerpt.
    double first = trace.t_s[best_start], last = first;
    for (std::size_t i = best_start; i < n && trace.t_s[i] < trace.t_s[best_start] + excerpt_s; ++i) {
      if (trace.flagged[i]) last = trace.t_s[i];
    }
    const double centre = best_count > 0 ? (first + last) / 2.0 : trace.t_s[n / 2];
    trace.excerpt_t0_s = std::max(trace.t_s.front(), centre - excerpt_s / 2.0);
    trace.excerpt_t1_s = std::min(trace.t_s.back(), trace.excerpt_t0_s + excerpt_s);
  }
  return trace;
}

std::vector<SummaryCell> SummaryCellsOf(const SweepData& sweep) {
  std::vector<SummaryCell> cells;
  for (int s = 0; s < static_cast<int>(sweep.settings.size()); ++s) {
    for (const std::string& method : sweep.methods) {
      SummaryCell cell;
      cell.method = method;
      cell.setting = s;
      for (const RunData& run : sweep.runs) {
        if (run.method != method || !(run.glitch == sweep.settings[s])) continue;
        double trans, rot;
        if (run.ok() && Stat(run.metrics, {"ate", "trans_m", "rmse"}, &trans) &&
            Stat(run.metrics, {"ate", "rot_deg", "rmse"}, &rot)) {
          cell.ate_trans_m.push_back(trans);
          cell.ate_rot_deg.push_back(rot);
        } else {
          ++cell.failed;
        }
      }
      if (!cell.ate_trans_m.empty() || cell.failed > 0) cells.push_back(cell);
    }
  }
  return cells;
}

}  // namespace vigil::plots
