// libFuzzer target: a recorded ground-truth trajectory (sim::ReadRecordedPoses), EuRoC CSV or TUM text,
// chosen by the reader from the content as for a user's file.
#include "fuzz/fuzz_input.h"
#include "sim/recorded_poses.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = vigil::fuzz::WriteInput("poses.txt", data, size);
  vigil::fuzz::ExpectOnlyInputErrors([&] { (void)vigil::sim::ReadRecordedPoses(path); });
  return 0;
}
