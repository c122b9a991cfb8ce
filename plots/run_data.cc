#include "plots/run_data.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "core/config.h"
#include "core/csv.h"
#include "core/dataset.h"
#include "core/error.h"
#include "core/output.h"
#include "experiments/sweeps/sweep_spec.h"

namespace vigil::plots {
namespace {

int MethodRank(const std::string& m) {
  if (m == "original") return 0;
  if (m == "trunc") return 1;
  if (m == "dtw") return 2;
  return 3;
}

std::string Number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

}  // namespace

std::string MethodName(detectors::DetectorType type) {
  switch (type) {
    case detectors::DetectorType::kThreshold:
      return "trunc";
    case detectors::DetectorType::kDtw:
      return "dtw";
    case detectors::DetectorType::kNone:
      return "original";
    default:
      return config::EnumNameOf(type, detectors::DetectorTypeNames());
  }
}

std::string MethodName(const detectors::DetectorOptions& detector) {
  if (detector.type == detectors::DetectorType::kDtw &&
      detector.dtw.normalization != detectors::SliceNormalization::kNone)
    return "normalized_dtw";
  return MethodName(detector.type);
}

bool MethodBefore(const std::string& a, const std::string& b) {
  const int ra = MethodRank(a), rb = MethodRank(b);
  return ra != rb ? ra < rb : a < b;
}

std::string GlitchSetting::Label() const {
  if (!enabled) return "no glitches";
  return "μ = " + Number(mean) + ", σ = " + Number(std);
}

bool GlitchSetting::operator<(const GlitchSetting& o) const {
  if (enabled != o.enabled) return !enabled;
  if (mean != o.mean) return mean < o.mean;
  return std < o.std;
}

bool GlitchSetting::operator==(const GlitchSetting& o) const {
  return enabled == o.enabled && (!enabled || (mean == o.mean && std == o.std));
}

GlitchSetting GlitchSettingOf(const experiments::RunConfig& config) {
  const auto& g = config.sim.glitch;
  GlitchSetting s;
  s.enabled = g.enabled && g.rate > 0.0;
  if (s.enabled) {
    s.mean = g.mean;
    s.std = g.std;
  }
  return s;
}

void ReadDetectionsCsv(const std::string& path, std::vector<int64_t>* t_ns, std::vector<uint8_t>* flagged) {
  CsvReader reader(path, 2, "detections layout (#timestamp [ns],flagged)");
  t_ns->clear();
  flagged->clear();
  while (reader.Next()) {
    const int64_t t = reader.Int(0), f = reader.Int(1);
    if (f != 0 && f != 1) reader.Fail("flagged: must be 0 or 1");
    if (!t_ns->empty() && t <= t_ns->back()) reader.Fail("timestamp: must increase strictly");
    t_ns->push_back(t);
    flagged->push_back(static_cast<uint8_t>(f));
  }
}

RunData LoadRunDirectory(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  RunData run;
  run.dir = dir;
  run.id = dir.filename().string();
  if (run.id.empty()) run.id = dir.parent_path().filename().string();
  const fs::path config_path = dir / "config.yaml";
  if (!fs::is_regular_file(config_path)) {
    throw InputError(config_path.string() + ": missing (not a run directory)");
  }
  run.config = experiments::LoadRunConfig(config_path.string());
  run.method = MethodName(run.config.detector);
  run.glitch = GlitchSettingOf(run.config);
  if (fs::is_regular_file(dir / "stamped_groundtruth.txt")) {
    run.groundtruth = ReadTumTrajectory((dir / "stamped_groundtruth.txt").string());
  }
  if (fs::is_regular_file(dir / "stamped_traj_estimate.txt")) {
    run.estimate = ReadTumTrajectory((dir / "stamped_traj_estimate.txt").string());
  }
  if (fs::is_regular_file(dir / "metrics.json")) {
    const fs::path path = dir / "metrics.json";
    run.metrics = nlohmann::json::parse(ReadFile(path), nullptr, /*allow_exceptions=*/false);
    if (run.metrics.is_discarded() || !run.metrics.is_object()) {
      throw InputError(path.string() + ": not a JSON object");
    }
  }
  if (fs::is_regular_file(dir / "detections.csv")) {
    ReadDetectionsCsv((dir / "detections.csv").string(), &run.detection_t_ns, &run.flagged);
  }
  return run;
}

namespace {

// The sweep's own method labels, by run id, and their order (its table_methods, then the other methods in
// the file's order): from DIR/sweep.yaml, the
// plan the runs were made from (empty when the directory has none, or one that no longer loads here: its
// base configuration moved, or $VIGIL_DATA unset; the runs' own configs then name the methods).
struct PlannedMethods {
  std::map<std::string, std::string> by_run;
  std::vector<std::string> order;
};

PlannedMethods PlannedMethodsOf(const std::filesystem::path& dir) {
  PlannedMethods out;
  const std::filesystem::path file = dir / "sweep.yaml";
  if (!std::filesystem::is_regular_file(file)) return out;
  experiments::SweepSpec spec;
  try {
    spec = experiments::LoadSweepSpec(file.string());
  } catch (const InputError&) {
    return out;
  }
  const std::vector<experiments::SweepCell> cells = experiments::EnumerateCells(spec);
  for (const experiments::SweepRunRef& run : experiments::EnumerateRuns(spec, cells))
    out.by_run[run.id] = spec.methods[cells[run.cell].method].label;
  out.order = spec.table_methods;
  for (const experiments::SweepSetting& m : spec.methods)
    if (std::find(out.order.begin(), out.order.end(), m.label) == out.order.end())
      out.order.push_back(m.label);
  return out;
}

}  // namespace

SweepData LoadSweepDirectory(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  SweepData sweep;
  const PlannedMethods planned = PlannedMethodsOf(dir);
  sweep.dir = dir;
  const fs::path runs_dir = dir / "runs";
  if (!fs::is_directory(runs_dir)) throw InputError(runs_dir.string() + ": missing (not a sweep directory)");
  std::vector<fs::path> run_dirs;
  for (const auto& entry : fs::directory_iterator(runs_dir)) {
    if (entry.is_directory() && fs::is_regular_file(entry.path() / "config.yaml") &&
        entry.path().filename().string().find(".tmp") == std::string::npos) {
      run_dirs.push_back(entry.path());
    }
  }
  std::sort(run_dirs.begin(), run_dirs.end());
  if (run_dirs.empty()) throw InputError(runs_dir.string() + ": no run directory (with config.yaml) inside");
  for (const fs::path& p : run_dirs) {
    sweep.runs.push_back(LoadRunDirectory(p));
    RunData& run = sweep.runs.back();
    if (const auto label = planned.by_run.find(run.id); label != planned.by_run.end())
      run.method = label->second;
    if (std::find(sweep.settings.begin(), sweep.settings.end(), run.glitch) == sweep.settings.end()) {
      sweep.settings.push_back(run.glitch);
    }
    if (std::find(sweep.methods.begin(), sweep.methods.end(), run.method) == sweep.methods.end()) {
      sweep.methods.push_back(run.method);
    }
  }
  std::sort(sweep.settings.begin(), sweep.settings.end());
  const auto rank = [&](const std::string& m) {  // the sweep's order first, then MethodBefore's
    return std::find(planned.order.begin(), planned.order.end(), m) - planned.order.begin();
  };
  std::sort(sweep.methods.begin(), sweep.methods.end(), [&](const std::string& a, const std::string& b) {
    return rank(a) != rank(b) ? rank(a) < rank(b) : MethodBefore(a, b);
  });
  return sweep;
}

namespace fs = std::filesystem;

namespace {

// `dir/name` when it is a file, else nothing with `why` naming it.
std::optional<fs::path> RecordedFile(const RunData& run, const char* name, std::string* why) {
  const fs::path path = run.dir / name;
  if (fs::is_regular_file(path)) return path;
  if (why != nullptr)
    *why = path.string() +
           " missing (the run was written without figure data: an older vigil, --no-figure-data "
           "or write_figure_data: false)";
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<Landmark>> RecordedLandmarks(const RunData& run, std::string* why) {
  const std::optional<fs::path> path = RecordedFile(run, dataset_files::kLandmarks, why);
  if (!path) return std::nullopt;
  return ReadLandmarksCsv(path->string());
}

std::optional<experiments::ImuAxisRecord> RecordedImuAxis(const RunData& run, std::string* why) {
  const std::optional<fs::path> path = RecordedFile(run, experiments::kImuAxisFile, why);
  if (!path) return std::nullopt;
  return experiments::ReadImuAxisCsv(path->string());
}

}  // namespace vigil::plots
