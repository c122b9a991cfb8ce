#include "experiments/results_csv.h"

#include <unistd.h>

#include <cmath>

#include "core/format.h"
#include "experiments/metrics_access.h"

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

ResultsCsvWriter::ResultsCsvWriter(const fs::path& sweep_dir, const SweepSpec& spec,
                                   std::vector<double> distances_m)
    : spec_(spec), distances_m_(std::move(distances_m)), final_(sweep_dir / "results.csv") {
  temp_ = final_;
  temp_ += ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error(temp_.string() + ": cannot open for writing");
  out_ << Header() << '\n';
}

ResultsCsvWriter::~ResultsCsvWriter() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    fs::remove(temp_, ec);
  }
}

void ResultsCsvWriter::Add(const SweepRunRef& run, const SweepCell& cell, const nlohmann::json& metrics) {
  out_ << Row(run, cell, metrics) << '\n';
  out_.flush();  // streamed: the partial file shows the runs so far
}

void ResultsCsvWriter::Commit() {
  out_.close();
  if (!out_) throw std::runtime_error(temp_.string() + ": write failed");
  fs::rename(temp_, final_);
  committed_ = true;
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
  h += ",estimator_resets,wall_time_s";
  return h;
}

std::string ResultsCsvWriter::Row(const SweepRunRef& run, const SweepCell& cell,
                                  const nlohmann::json& m) const {
  std::string r = run.id;
  for (std::size_t a = 0; a < spec_.axes.size(); ++a)
    r += "," + spec_.axes[a].settings[cell.setting[a]].label;
  r += "," + spec_.methods[cell.method].label + "," + std::to_string(run.seed);
  r += "," + Text(MetricText(m, "status")) + "," + Text(MetricText(m, "failure_reason"));
  for (const char* stat : {"rmse", "mean", "median", "std", "max"})
    r += "," + Number(MetricNumber(m, {"ate", "trans_m", stat}));
  r += "," + Number(MetricNumber(m, {"ate", "rot_deg", "rmse"}));
  for (double d : distances_m_) {
    const nlohmann::json* e = RelativeEntry(m, d);
    const nlohmann::json none;
    const nlohmann::json& entry = e ? *e : none;
    r += "," + Number(MetricNumber(entry, {"trans_m", "mean"})) + "," +
         Number(MetricNumber(entry, {"yaw_deg", "mean"})) + "," +
         Number(MetricNumber(entry, {"trans_m", "n"}));
  }
  const auto det = m.find("detection");
  r += "," + (det != m.end() ? Text(MetricText(*det, "detector")) : std::string());
  for (const char* key : {"flagged_samples", "glitched_samples", "precision", "recall", "f1"})
    r += "," + Number(MetricNumber(m, {"detection", key}));
  r += "," + Number(MetricNumber(m, {"detection", "imu_rmse_vs_clean", "raw"}));
  r += "," + Number(MetricNumber(m, {"detection", "imu_rmse_vs_clean", "cleaned"}));
  r += "," + Number(MetricNumber(m, {"estimator", "resets"}));
  r += "," + Number(MetricNumber(m, {"wall_time_s", "total"}));
  return r;
}

}  // namespace vigil::experiments
