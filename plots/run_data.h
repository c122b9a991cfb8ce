// What the figures read from run, sweep and dataset directories (docs/formats.md), loaded through the
// contract only.
//
// A run is classified by its own config.yaml: the method is the detector (threshold -> "trunc", dtw -> "dtw",
// none -> "original", others by their name) and the glitch setting is (glitch.enabled, glitch.mean,
// glitch.std). Sweep runs are grouped by these, never by parsing run ids; in a sweep directory whose
// sweep.yaml loads, a run's method is instead the sweep's own label of it (from the plan of that file), so
// that methods with the same detector, e.g. vigil's `trunc` and OpenVINS's `openvins_trunc`
// (configs/estimators_glitch_study.yaml), stay apart.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/dataset.h"
#include "core/types.h"
#include "experiments/runs/imu_axis_record.h"
#include "experiments/runs/run_config.h"

namespace vigil::plots {

// The paper's name of a detector: threshold -> "trunc", dtw -> "dtw", none -> "original", else its type name.
std::string MethodName(detectors::DetectorType type);
// The same for a run's detector options: dtw with a normalization other than none is "normalized_dtw".
std::string MethodName(const detectors::DetectorOptions& detector);
// Order of methods in legends: original, trunc, dtw, then the others alphabetically.
bool MethodBefore(const std::string& a, const std::string& b);

struct GlitchSetting {
  bool enabled = false;
  double mean = 0.0;
  double std = 0.0;

  // "no glitches" or "μ = 2, σ = 1" (units of the glitched axes).
  std::string Label() const;
  bool operator<(const GlitchSetting& o) const;
  bool operator==(const GlitchSetting& o) const;
};
GlitchSetting GlitchSettingOf(const experiments::RunConfig& config);

struct RunData {
  std::filesystem::path dir;
  std::string id;  // the directory's name
  experiments::RunConfig config;
  std::string method;
  GlitchSetting glitch;
  Trajectory groundtruth;               // stamped_groundtruth.txt (empty when absent)
  Trajectory estimate;                  // stamped_traj_estimate.txt (empty when absent)
  nlohmann::json metrics;               // metrics.json (null when absent)
  std::vector<int64_t> detection_t_ns;  // detections.csv (empty when absent)
  std::vector<uint8_t> flagged;

  // The run finished and was evaluated ("ok", or "diverged": its errors are measured, only large).
  bool ok() const {
    if (!metrics.is_object()) return false;
    const std::string status = metrics.value("status", "");
    return status == "ok" || status == "diverged";
  }
};

// Reads a run directory; config.yaml is required, the other files are optional. Bad files throw InputError.
RunData LoadRunDirectory(const std::filesystem::path& dir);

// What a run recorded for its figures (run.h's figure data), read when a figure needs it: landmarks.csv and
// imu_axis.csv (experiments/runs/imu_axis_record.h). Nothing when the file is absent (a run written before
// runs recorded it, or with --no-figure-data / write_figure_data: false); `why` then says which file is
// missing. A file that is there but bad throws InputError.
std::optional<std::vector<Landmark>> RecordedLandmarks(const RunData& run, std::string* why);
std::optional<experiments::ImuAxisRecord> RecordedImuAxis(const RunData& run, std::string* why);

struct SweepData {
  std::filesystem::path dir;
  std::vector<RunData> runs;            // runs/<id>/ in id order
  std::vector<GlitchSetting> settings;  // distinct settings, sorted
  std::vector<std::string>
      methods;  // distinct methods: the sweep's table_methods, its other methods, then MethodBefore's
};

// Reads every run directory under dir/runs (entries without config.yaml, e.g. unfinished temporaries, are
// skipped). InputError when dir/runs does not exist or holds no run.
SweepData LoadSweepDirectory(const std::filesystem::path& dir);

// Reads detections.csv ("#timestamp [ns],flagged").
void ReadDetectionsCsv(const std::string& path, std::vector<int64_t>* t_ns, std::vector<uint8_t>* flagged);

}  // namespace vigil::plots
