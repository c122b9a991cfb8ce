// libFuzzer target: a run configuration file (YAML binding, bounds, cross-key checks): `vigil config FILE`.
#include "experiments/runs/run_config.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = vigil::fuzz::WriteInput("config.yaml", data, size);
  vigil::fuzz::ExpectOnlyInputErrors([&] {
    vigil::experiments::RunConfig config = vigil::experiments::LoadRunConfig(path);
    (void)vigil::config::ToYaml(config);
  });
  return 0;
}
