// libFuzzer target: a run's metrics.json as `vigil tables` reads it (ReadRunMetrics for the run of seed 1;
// in memory).
#include "experiments/runs/run_metrics_file.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const vigil::TextFile file{"metrics.json", std::string(reinterpret_cast<const char*>(data), size)};
  vigil::fuzz::ExpectOnlyInputErrors([&] {
    const nlohmann::json metrics = vigil::experiments::ReadRunMetricsText(file, 1);
    if (!metrics.is_object()) std::abort();  // accepted metrics are an object
  });
  return 0;
}
