#include "sim/timing_faults.h"

#include <algorithm>
#include <cmath>

#include "core/random.h"

namespace vigil::sim {
namespace {

// What happens to each sample.
struct SamplePlan {
  bool drop = false;
  bool duplicate = false;
  int64_t jitter_ns = 0;
};

std::vector<SamplePlan> PlanTimingFaults(const TimingFaultOptions& o, double rate_hz, uint64_t seed,
                                         std::size_t n) {
  std::vector<SamplePlan> plan(n);
  const double max_jitter_s = 0.45 / rate_hz;
  Rng drop_rng(seed, "imu_drop"), duplicate_rng(seed, "imu_duplicate"), jitter_rng(seed, "imu_jitter");
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (o.drop_rate > 0.0) plan[k].drop = drop_rng.Bernoulli(o.drop_rate);
    if (o.duplicate_rate > 0.0) plan[k].duplicate = duplicate_rng.Bernoulli(o.duplicate_rate);
    if (o.jitter_std_s > 0.0)
      plan[k].jitter_ns =
          SToNs(std::clamp(jitter_rng.Normal(0.0, o.jitter_std_s), -max_jitter_s, max_jitter_s));
  }
  return plan;
}

}  // namespace

void ApplyTimingFaults(const TimingFaultOptions& options, double rate_hz, uint64_t seed, ImuStream* imu,
                       ImuStream* imu_clean, std::vector<GlitchRecord>* records) {
  if (options.drop_rate <= 0.0 && options.duplicate_rate <= 0.0 && options.jitter_std_s <= 0.0) return;
  const std::vector<SamplePlan> plan = PlanTimingFaults(options, rate_hz, seed, imu->size());
  ImuStream out, out_clean;
  std::vector<GlitchRecord> out_records;
  std::size_t r = 0;  // next value record
  int64_t last_written_ns = 0;
  for (std::size_t k = 0; k < imu->size(); ++k) {
    const int64_t t_true = (*imu)[k].t_ns;
    const SamplePlan& p = plan[k];
    if (p.drop) {
      while (r < records->size() && (*records)[r].t_ns == t_true) ++r;
      out_records.push_back({t_true, ImuAxis::kAz, 0.0, FaultKind::kDrop});
      continue;
    }
    const int64_t t_new = p.duplicate && !out.empty() ? last_written_ns : t_true + p.jitter_ns;
    for (; r < records->size() && (*records)[r].t_ns == t_true; ++r) {
      out_records.push_back((*records)[r]);
      out_records.back().t_ns = t_new;
    }
    if (t_new != t_true)
      out_records.push_back({t_new, ImuAxis::kAz, static_cast<double>(t_new - t_true),
                             p.duplicate ? FaultKind::kDuplicate : FaultKind::kJitter});
    out.push_back((*imu)[k]);
    out.back().t_ns = t_new;
    out_clean.push_back((*imu_clean)[k]);
    out_clean.back().t_ns = t_new;
    last_written_ns = t_new;
  }
  std::stable_sort(out_records.begin(), out_records.end(),
                   [](const GlitchRecord& a, const GlitchRecord& b) { return a.t_ns < b.t_ns; });
  *imu = std::move(out);
  *imu_clean = std::move(out_clean);
  *records = std::move(out_records);
}

}  // namespace vigil::sim
