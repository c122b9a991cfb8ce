// From loaded run and sweep directories (run_data.h) and dataset directories to the plain data of figures.h.
#pragma once

#include <string>
#include <vector>

#include "core/dataset.h"
#include "plots/figures.h"
#include "plots/run_data.h"

namespace vigil::plots {

ScenarioData ScenarioDataOf(const Dataset& dataset, const std::string& title);
// A run's scenario: its ground truth at the camera frames and the landmarks it recorded.
ScenarioData ScenarioDataOf(const Trajectory& groundtruth, const std::vector<Landmark>& landmarks,
                            const std::string& title);

// The IMU axis a config glitches (the first of glitch.axes; a_z when none).
ImuAxis GlitchedAxis(const experiments::RunConfig& config);
// Measured vs clean samples of `axis` (clean = imu_clean, or the measured stream when that is empty).
ImuTrace ImuTraceOf(const Dataset& dataset, ImuAxis axis, const std::string& label);
// Raw vs clean samples of a run's recorded axis (clean = raw when the run had no glitch-free stream).
ImuTrace ImuTraceOf(const experiments::ImuAxisRecord& record, const std::string& label);

// Ground truth of the first run plus each run's estimate aligned with its evaluation.align (runs without an
// estimate are left out).
TrajectoryPanel TrajectoryPanelOf(const std::string& label, const std::vector<const RunData*>& runs);

// Boxes of one run: from its metrics' STATS (whiskers min/max, box mean +- std clipped to them, line median).
RelativeErrorRow RelativeErrorRowOfRun(const std::string& label, const RunData& run);
// Boxes over runs: quartiles of the per-run mean errors, per method (successful runs only).
RelativeErrorRow RelativeErrorRowOfRuns(const std::string& label, const std::vector<const RunData*>& runs);

// Figure 5 data: the raw, clean, mitigated values and flags the run recorded (imu_axis.csv); the excerpt is
// the window of `excerpt_s` with the most flagged samples.
DetectionTrace DetectionTraceOf(const RunData& run, const experiments::ImuAxisRecord& record,
                                double excerpt_s);

// Figure 6 cells: ATE RMSE of every run, by (setting, method).
std::vector<SummaryCell> SummaryCellsOf(const SweepData& sweep);

}  // namespace vigil::plots
