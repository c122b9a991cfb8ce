// libFuzzer target: a regression baseline (ReadBaseline, as `vigil regress --baseline FILE` reads it; in
// memory, the file reading is the CSV targets' ReadFile).
#include "experiments/sweeps/regression_baseline.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const vigil::TextFile file{"baseline.json", std::string(reinterpret_cast<const char*>(data), size)};
  vigil::fuzz::ExpectOnlyInputErrors([&] {
    std::vector<vigil::experiments::RegressionCell> cells;
    vigil::experiments::RegressionTolerance tolerance;
    vigil::experiments::ReadBaselineText(file, &cells, &tolerance);
    if (cells.empty()) std::abort();  // a baseline read without error compares at least one cell
  });
  return 0;
}
