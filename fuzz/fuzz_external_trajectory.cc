// libFuzzer target: the trajectory an external estimator wrote (experiments::ReadExternalTrajectory). The
// first byte picks the format and time unit; the rest is the file. The reader never throws: every problem
// is a one-line failure reason, and anything else (an exception, a crash, a hang) is a finding.
#include <cstdio>
#include <cstdlib>

#include "experiments/external/external_trajectory.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace vigil::experiments;
  if (size == 0) return 0;
  const TrajectoryFormat format = (data[0] & 1) ? TrajectoryFormat::kEuroc : TrajectoryFormat::kTum;
  const TimeUnit unit = (data[0] & 2) ? TimeUnit::kNanoseconds : TimeUnit::kSeconds;
  const std::string path = vigil::fuzz::WriteInput("traj.txt", data + 1, size - 1);
  // The recording's span: 20 s from 0, as a simulated run's (the seeds are the first rows of one).
  const ExternalTrajectory read = ReadExternalTrajectory(path, format, unit, 0, 20000000000);
  for (const char c : read.failure)
    if (c == '\n' || static_cast<unsigned char>(c) < 0x20) {
      std::fprintf(stderr, "failure reason is not one printable line: %s\n", read.failure.c_str());
      std::abort();
    }
  return 0;
}
