// libFuzzer target: a sweep file (LoadSweepSpec, every cell's configuration and the resolved sweep.yaml). Its
// `base` may name base.yaml, a copy of configs/paper.yaml beside it.
#include <filesystem>

#include "core/output.h"
#include "experiments/sweeps/sweep_spec.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool base_written = [] {
    const std::string base = vigil::ReadFile(std::string(VIGIL_SOURCE_DIR) + "/configs/paper.yaml");
    vigil::fuzz::WriteInput("base.yaml", reinterpret_cast<const uint8_t*>(base.data()), base.size());
    vigil::fuzz::WriteInput("paper.yaml", reinterpret_cast<const uint8_t*>(base.data()), base.size());
    return true;
  }();
  (void)base_written;
  const std::string path = vigil::fuzz::WriteInput("sweep.yaml", data, size);
  vigil::fuzz::ExpectOnlyInputErrors([&] {
    const vigil::experiments::SweepSpec spec = vigil::experiments::LoadSweepSpec(path);
    if (spec.cell_count() > 64) return;  // resolving thousands of cells only repeats the same code
    for (const vigil::experiments::SweepCell& cell : vigil::experiments::EnumerateCells(spec))
      (void)vigil::experiments::ResolveCellConfig(spec, cell);
    (void)vigil::experiments::ResolvedSweepYaml(spec);
  });
  return 0;
}
