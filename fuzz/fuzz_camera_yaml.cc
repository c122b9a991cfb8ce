// libFuzzer target: a dataset's camera.yaml (ReadCameraYaml).
#include "core/dataset.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = vigil::fuzz::WriteInput("camera.yaml", data, size);
  vigil::fuzz::ExpectOnlyInputErrors([&] { (void)vigil::ReadCameraYaml(path); });
  return 0;
}
