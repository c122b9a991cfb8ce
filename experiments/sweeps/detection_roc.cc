#include "experiments/sweeps/detection_roc.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/format.h"
#include "core/output.h"
#include "evaluation/metrics_access.h"
#include "experiments/sweeps/sweep_aggregate.h"

namespace vigil::experiments {
namespace {

std::string CurveOf(const std::string& method) {
  const auto cut = method.rfind('_');
  return cut == std::string::npos ? method : method.substr(0, cut);
}

// The line of `label:` in the sweep file (0 when not found): method labels may hold '.', which KeyLine
// reads as nesting.
int LabelLine(const std::string& path, const std::string& label) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return 0;
  std::istringstream in(ReadFile(path, 16 << 20));
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::size_t start = line.find_first_not_of(" \t");
    if (start != std::string::npos && line.compare(start, label.size() + 1, label + ":") == 0) return n;
  }
  return 0;
}

}  // namespace

void CheckRocMethodLabels(const SweepSpec& spec) {
  const std::vector<SweepCell> cells = EnumerateCells(spec);  // the first cells: one per method, in order
  for (std::size_t i = 0; i < spec.methods.size() && i < cells.size(); ++i) {
    const SweepSetting& m = spec.methods[i];
    auto fail = [&](const std::string& why) {
      throw InputError(Located(spec.path, LabelLine(spec.path, m.label), "methods: " + m.label + ": " + why));
    };
    const std::size_t cut = m.label.rfind('_');
    double point = 0;
    if (cut == std::string::npos || cut == 0 || !ParseDouble(m.label.substr(cut + 1), &point))
      fail("a ROC method label is <curve>_<point>, the point a finite number (e.g. hampel_3)");
    const std::string curve = m.label.substr(0, cut);
    for (char c : curve)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        fail("the curve name may hold letters, digits and '_'");
    const std::string detector =
        config::EnumNameOf(ResolveCellConfig(spec, cells[i]).detector.type, detectors::DetectorTypeNames());
    const bool named_after = curve == detector || (curve.size() > detector.size() + 1 &&
                                                   curve.compare(curve.size() - detector.size() - 1,
                                                                 std::string::npos, "_" + detector) == 0);
    if (!named_after)
      fail("the curve '" + curve + "' runs the " + detector + " detector: name it " + detector +
           "_<point> (or " + "<variant>_" + detector + "_<point>)");
  }
}

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
    const double samples = evaluation::MetricNumber(d, {"samples"}),
                 flagged = evaluation::MetricNumber(d, {"flagged_samples"});
    const double glitched = evaluation::MetricNumber(d, {"glitched_samples"});
    const double detected = evaluation::MetricNumber(d, {"detected_glitched_samples"});
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
