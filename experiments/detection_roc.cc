#include "experiments/detection_roc.h"

#include <cmath>

#include "core/error.h"
#include "core/format.h"
#include "experiments/metrics_access.h"
#include "experiments/sweep_aggregate.h"

namespace vigil::experiments {
namespace {

std::string CurveOf(const std::string& method) {
  const auto cut = method.rfind('_');
  return cut == std::string::npos ? method : method.substr(0, cut);
}

}  // namespace

std::vector<RocCurve> ReadDetectionRoc(const std::filesystem::path& dir, const SweepSpec& spec) {
  // Pooled counts per method: detected glitched samples, glitched, false flags, normal samples.
  struct Counts {
    double detected = 0, glitched = 0, false_flags = 0, normal = 0;
    int runs = 0;
  };
  std::vector<Counts> counts(spec.methods.size());
  AggregateSweep(dir, spec, {}, [&](const SweepRunRef&, const SweepCell& cell, const nlohmann::json* m) {
    if (m == nullptr || !m->contains("detection")) return;
    const nlohmann::json& d = m->at("detection");
    const double samples = MetricNumber(d, {"samples"}), flagged = MetricNumber(d, {"flagged_samples"});
    const double glitched = MetricNumber(d, {"glitched_samples"});
    const double detected = MetricNumber(d, {"detected_glitched_samples"});
    if (!std::isfinite(samples) || !std::isfinite(flagged) || !std::isfinite(glitched) ||
        !std::isfinite(detected))
      return;
    Counts& c = counts[static_cast<std::size_t>(cell.method)];
    c.detected += detected;
    c.glitched += glitched;
    c.false_flags += flagged - detected;
    c.normal += samples - glitched;
    ++c.runs;
  });
  std::vector<RocCurve> curves;
  for (std::size_t m = 0; m < spec.methods.size(); ++m) {
    const Counts& c = counts[m];
    if (c.runs == 0) continue;
    const std::string detector = CurveOf(spec.methods[m].label);
    if (curves.empty() || curves.back().detector != detector) curves.push_back({detector, {}});
    RocPoint p;
    p.method = spec.methods[m].label;
    p.tpr = c.glitched > 0 ? c.detected / c.glitched : std::nan("");
    p.fpr = c.normal > 0 ? c.false_flags / c.normal : std::nan("");
    p.glitched = c.glitched;
    p.normal = c.normal;
    p.runs = c.runs;
    curves.back().points.push_back(p);
  }
  if (curves.empty()) throw InputError(spec.path + ": no run of the sweep recorded detection statistics");
  return curves;
}

std::string DetectionRocMarkdown(const std::vector<RocCurve>& curves) {
  std::string s = "# Detector ROC (per sample, pooled over runs)\n";
  for (const RocCurve& curve : curves) {
    s += "\n## " + curve.detector + "\n\n| point | TPR | FPR | FPR [%] | runs |\n|---|---|---|---|---|\n";
    for (const RocPoint& p : curve.points)
      s += "| " + p.method + " | " + FormatFixed(p.tpr, 4) + " | " + FormatFixed(p.fpr, 6) + " | " +
           FormatFixed(100.0 * p.fpr, 3) + " | " + std::to_string(p.runs) + " |\n";
  }
  return s;
}

}  // namespace vigil::experiments
