#include "experiments/sweeps/results_csv.h"

#include <cmath>

#include "core/format.h"
#include "core/staging.h"
#include "evaluation/metrics_access.h"

namespace vigil::experiments {
namespace fs = std::filesystem;
namespace {

std::string Number(double v) { return std::isfinite(v) ? FormatDouble(v) : std::string(); }

// Free text inside a CSV field: no separators, no line breaks.
std::string Text(std::string s) {
  for (char& c : s)
    if (c == ',' || c == '\n' || c == '\r') c = c == ',' ? ';' : ' ';
  return s;
}

}  // namespace

void ResultsCsvWriter::Stream::Open(const fs::path& path, const std::string& header) {
  final = path;
  temp = StagingPathFor(path);
  out.open(temp, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(temp.string() + ": cannot open for writing");
  out << header << '\n';
}

void ResultsCsvWriter::Stream::Commit() {
  out.close();
  if (!out) throw std::runtime_error(temp.string() + ": write failed");
  fs::rename(temp, final);
}

void ResultsCsvWriter::Stream::Abandon() {
  out.close();
  std::error_code ec;
  fs::remove(temp, ec);
}

ResultsCsvWriter::ResultsCsvWriter(const fs::path& sweep_dir, const SweepSpec& spec,
                                   std::vector<double> distances_m)
    : spec_(spec), distances_m_(std::move(distances_m)) {
  results_.Open(sweep_dir / "results.csv", Header());
  timing_.Open(sweep_dir / "timing.csv", TimingHeader());
}

ResultsCsvWriter::~ResultsCsvWriter() {
  if (!committed_) {
    results_.Abandon();
    timing_.Abandon();
  }
}

void ResultsCsvWriter::Add(const SweepRunRef& run, const SweepCell& cell, const nlohmann::json& metrics) {
  results_.out << Row(run, cell, metrics) << '\n';
  results_.out.flush();  // streamed: the partial file shows the runs so far
  timing_.out << TimingRow(run, metrics) << '\n';
  timing_.out.flush();
}

void ResultsCsvWriter::Commit() {
  timing_.Commit();
  results_.Commit();
  committed_ = true;
}

std::string ResultsCsvWriter::TimingHeader() {
  return "#id,simulate_s,templates_s,detect_s,estimate_s,evaluate_s,total_s,external_process_s";
}

std::string ResultsCsvWriter::TimingRow(const SweepRunRef& run, const nlohmann::json& m) {
  std::string r = run.id;
  for (const char* stage : {"simulate", "templates", "detect", "estimate", "evaluate", "total"})
    r += "," + Number(evaluation::MetricNumber(m, {"wall_time_s", stage}));
  r += "," + Number(evaluation::MetricNumber(m, {"external", "wall_time_s", "process"}));  // empty: built-in
  return r;
}

std::string ResultsCsvWriter::Header() const {
  std::string h = "#id";
  for (const auto& a : spec_.axes) h += "," + a.key;
  h += ",method,seed,status,failure_reason";
  h += ",ate_trans_rmse_m,ate_trans_mean_m,ate_trans_median_m,ate_trans_std_m,ate_trans_max_m,ate_rot_rmse_"
       "deg";
  for (double d : distances_m_) {
    const std::string s = FormatDouble(d);
    h += ",re_trans_mean_m_" + s + ",re_yaw_mean_deg_" + s + ",re_n_" + s;
  }
  h += ",detector,flagged_samples,glitched_samples,precision,recall,f1,imu_rmse_raw,imu_rmse_cleaned";
  h += ",false_positive_rate,segment_precision,segment_f1";
  h += ",estimator_resets";
  h += ",nees_position_mean,nees_orientation_mean";
  h += ",coverage";
  return h;
}

std::string ResultsCsvWriter::Row(const SweepRunRef& run, const SweepCell& cell,
                                  const nlohmann::json& m) const {
  std::string r = run.id;
  for (std::size_t a = 0; a < spec_.axes.size(); ++a)
    r += "," + spec_.axes[a].settings[cell.setting[a]].label;
  r += "," + spec_.methods[cell.method].label + "," + std::to_string(run.seed);
  r += "," + Text(evaluation::MetricText(m, "status")) + "," +
       Text(evaluation::MetricText(m, "failure_reason"));
  for (const char* stat : {"rmse", "mean", "median", "std", "max"})
    r += "," + Number(evaluation::MetricNumber(m, {"ate", "trans_m", stat}));
  r += "," + Number(evaluation::MetricNumber(m, {"ate", "rot_deg", "rmse"}));
  for (double d : distances_m_) {
    const nlohmann::json* e = evaluation::RelativeEntry(m, d);
    const nlohmann::json none;
    const nlohmann::json& entry = e ? *e : none;
    r += "," + Number(evaluation::MetricNumber(entry, {"trans_m", "mean"})) + "," +
         Number(evaluation::MetricNumber(entry, {"yaw_deg", "mean"})) + "," +
         Number(evaluation::MetricNumber(entry, {"trans_m", "n"}));
  }
  const auto det = m.find("detection");
  r += "," + (det != m.end() ? Text(evaluation::MetricText(*det, "detector")) : std::string());
  for (const char* key : {"flagged_samples", "glitched_samples", "precision", "recall", "f1"})
    r += "," + Number(evaluation::MetricNumber(m, {"detection", key}));
  r += "," + Number(evaluation::MetricNumber(m, {"detection", "imu_rmse_vs_clean", "raw"}));
  r += "," + Number(evaluation::MetricNumber(m, {"detection", "imu_rmse_vs_clean", "cleaned"}));
  for (const char* key : {"false_positive_rate", "segment_precision", "segment_f1"})
    r += "," + Number(evaluation::MetricNumber(m, {"detection", key}));
  r += "," + Number(evaluation::MetricNumber(m, {"estimator", "resets"}));
  r += "," + Number(evaluation::MetricNumber(m, {"nees", "position", "mean"}));
  r += "," + Number(evaluation::MetricNumber(m, {"nees", "orientation", "mean"}));
  r += "," + Number(evaluation::MetricNumber(m, {"coverage"}));
  return r;
}

}  // namespace vigil::experiments
