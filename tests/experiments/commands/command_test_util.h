// Helpers of the command-library tests: a short simulated recording written as a dataset directory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>

#include "core/dataset.h"
#include "core/output.h"
#include "sim/simulator.h"

namespace vigil::testing {

// A `duration_s` ellipse recording of `seed` (glitches on when `glitches`) written into `dir` (created).
inline Dataset WriteSimulatedRecording(const std::filesystem::path& dir, double duration_s, uint64_t seed,
                                       bool glitches) {
  sim::SimOptions options;
  options.duration_s = duration_s;
  options.glitch.enabled = glitches;
  options.glitch.rate = 0.02;
  options.glitch.mean = 30.0;
  const Dataset dataset = sim::Simulate(options, seed);
  std::filesystem::create_directories(dir);
  WriteDataset(dir, dataset);
  return dataset;
}

// Whether `dir` holds nothing but what `names` lists (for "nothing half-written" checks: no staging left).
inline bool OnlyEntries(const std::filesystem::path& dir, const std::set<std::string>& names) {
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (!names.count(entry.path().filename().string())) return false;
  return true;
}

}  // namespace vigil::testing
