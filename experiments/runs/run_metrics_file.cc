#include "experiments/runs/run_metrics_file.h"

#include <cmath>
#include <cstdio>

#include "core/output.h"
#include "experiments/runs/json_document.h"

namespace vigil::experiments {
namespace {
using nlohmann::json;

class MetricsCheck {
 public:
  explicit MetricsCheck(const JsonDocument& doc) : doc_(doc) {}

  // The value at `pointer` when present (nullptr otherwise).
  const json* Find(const std::string& pointer) const {
    const json::json_pointer p(pointer);
    return doc_.root().contains(p) ? &doc_.root().at(p) : nullptr;
  }
  const json* Object(const std::string& pointer) const {
    const json* v = Find(pointer);
    if (v && !v->is_object()) doc_.Fail(pointer, std::string("expected an object, got ") + v->type_name());
    return v;
  }
  // A number in [lo, hi] or null, when present.
  void Number(const std::string& pointer, double lo, double hi) const {
    const json* v = Find(pointer);
    if (!v || v->is_null()) return;
    if (!v->is_number()) doc_.Fail(pointer, std::string("expected a number, got ") + v->type_name());
    const double x = v->get<double>();
    if (!(x >= lo && x <= hi))
      doc_.Fail(pointer, "must be in [" + Show(lo) + ", " + Show(hi) + "], got " + v->dump());
  }
  void Count(const std::string& pointer) const {
    const json* v = Find(pointer);
    if (!v || v->is_null()) return;
    if (!v->is_number_unsigned() &&
        !(v->is_number_float() && v->get<double>() >= 0 && v->get<double>() <= kMaxMetricValue &&
          std::floor(v->get<double>()) == v->get<double>()))
      doc_.Fail(pointer, "expected an integer >= 0, got " + v->dump());
  }
  void Stats(const std::string& pointer) const {
    if (!Object(pointer)) return;
    for (const char* key : {"rmse", "mean", "median", "std", "min", "max"})
      Number(pointer + "/" + key, 0, kMaxMetricValue);
    Count(pointer + "/n");
  }

 private:
  static std::string Show(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", x);
    return buf;
  }
  const JsonDocument& doc_;
};

}  // namespace

json ReadRunMetrics(const std::string& path, uint64_t seed) {
  return ReadRunMetricsText({path, ReadFile(path, 64 << 20)}, seed);
}

json ReadRunMetricsText(const TextFile& file, uint64_t seed) {
  const JsonDocument doc(file.path, file.text);
  const json& m = doc.root();
  if (!m.is_object()) doc.Fail("", std::string("expected a JSON object, got ") + m.type_name());
  const MetricsCheck check(doc);
  const json* status = check.Find("/status");
  if (!status || !status->is_string() ||
      (*status != "ok" && *status != "diverged" && *status != "failed" && *status != "inconclusive"))
    doc.Fail("/status", "expected \"ok\", \"diverged\", \"inconclusive\" or \"failed\"");
  if (const json* r = check.Find("/failure_reason"); r && !r->is_string())
    doc.Fail("/failure_reason", std::string("expected a string, got ") + r->type_name());
  // Every run vigil writes records its seed (one that failed before it started has none): when there, it must
  // be this run's.
  const json* s = check.Find("/seed");
  if (s && !(s->is_number_unsigned() && s->get<uint64_t>() == seed))
    doc.Fail("/seed", s->dump() + " is not this run's seed (" + std::to_string(seed) +
                          "): the metrics of another run?");
  check.Number("/duration_s", 0, kMaxMetricValue);
  if (const json* wall = check.Object("/wall_time_s"))
    for (const auto& [stage, value] : wall->items())
      check.Number("/wall_time_s/" + PointerToken(stage), 0, kMaxMetricValue);
  if (check.Object("/ate")) {
    check.Stats("/ate/trans_m");
    check.Stats("/ate/rot_deg");
  }
  if (const json* rel = check.Find("/relative")) {
    if (!rel->is_array()) doc.Fail("/relative", std::string("expected a list, got ") + rel->type_name());
    for (std::size_t i = 0; i < rel->size(); ++i) {
      const std::string p = "/relative/" + std::to_string(i);
      if (!check.Object(p)) continue;
      const json* d = check.Find(p + "/distance_m");
      if (!d || !d->is_number() || !(d->get<double>() > 0 && d->get<double>() <= kMaxMetricValue))
        doc.Fail(p + "/distance_m", "expected a number in (0, 1e9]");
      check.Stats(p + "/trans_m");
      check.Stats(p + "/yaw_deg");
    }
  }
  if (check.Object("/detection")) {
    check.Count("/detection/flagged_samples");
    check.Count("/detection/glitched_samples");
    for (const char* key : {"precision", "recall", "f1"})
      check.Number(std::string("/detection/") + key, 0, 1);
  }
  return m;
}

}  // namespace vigil::experiments
