// Helpers of the sweep tests: a small sweep file on a short scenario and fake run results (no estimator).
#pragma once

#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "core/output.h"
#include "core/random.h"
#include "experiments/runs/run_config.h"
#include "experiments/sweeps/sweep_runner.h"
#include "tests/core/test_util.h"

namespace vigil::experiments::testing {

// Writes base.yaml (a 4 s ellipse) and sweep.yaml (glitch settings x methods x seeds) into `dir`.
inline std::string WriteSmallSweep(const vigil::testing::TempDir& dir, const std::string& methods,
                                   const std::string& seeds = "{count: 3, first: 1}") {
  dir.File("base.yaml", "seed: 1\nduration_s: 4\nglitch: {enabled: true, rate: 0.02, axes: [az]}\n");
  return dir.File("sweep.yaml",
                  "base: base.yaml\n"
                  "set: {camera.pixel_noise_px: 0.5}\n"
                  "axes:\n"
                  "  glitch:\n"
                  "    noise_0_1: {mean: 0, std: 1}\n"
                  "    noise_50_10: {mean: 50, std: 10}\n"
                  "methods:\n" +
                      methods + "seeds: " + seeds + "\ntemplate_seed: 1000\n");
}

// Metrics shaped like metrics.json whose values depend only on the configuration and the seed: what a
// deterministic run gives. Glitch size, detector and seed all change the numbers.
inline nlohmann::json FakeMetrics(const RunConfig& config) {
  Rng rng(config.seed, "fake_run");
  const double glitch =
      config.sim.glitch.enabled ? std::abs(config.sim.glitch.mean) + config.sim.glitch.std : 0.0;
  const double cleaned = config.detector.type == detectors::DetectorType::kNone ? 1.0 : 0.05;
  const double ate = 0.05 + 0.01 * glitch * cleaned + 0.01 * rng.Uniform();
  nlohmann::json m;
  m["status"] = "ok";
  m["failure_reason"] = "";
  m["seed"] = config.seed;
  m["duration_s"] = config.sim.duration_s;
  m["wall_time_s"] = {{"total", 0.001 * static_cast<double>(config.seed)}};  // deterministic on purpose
  m["ate"] = {{"align", "posyaw"},
              {"trans_m",
               {{"rmse", ate},
                {"mean", 0.9 * ate},
                {"median", 0.8 * ate},
                {"std", 0.1 * ate},
                {"min", 0.0},
                {"max", 2 * ate},
                {"n", 100}}},
              {"rot_deg", {{"rmse", 10 * ate}}}};
  nlohmann::json rel = nlohmann::json::array();
  for (double d : config.evaluation.distances_m)
    rel.push_back({{"distance_m", d},
                   {"trans_m", {{"mean", ate * d / 7.0}, {"n", 10 + config.seed}}},
                   {"yaw_deg", {{"mean", 0.1 * d * ate}, {"n", 10 + config.seed}}}});
  m["relative"] = rel;
  m["detection"] = {{"detector", config.detector.type == detectors::DetectorType::kNone ? "none" : "other"},
                    {"flagged_samples", 10},
                    {"glitched_samples", 8},
                    {"precision", 0.7},
                    {"recall", 0.875}};
  return m;
}

inline void SleepMs(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

// An executor that writes the run's config.yaml and returns FakeMetrics, after `sleep_ms` (so that a sweep
// lasts long enough to be killed in the middle).
inline RunExecutor SlowFakeExecutor(int sleep_ms) {
  return [sleep_ms](const RunConfig& c, const RunOptions&, const std::filesystem::path& d) {
    SleepMs(sleep_ms);
    RunConfig copy = c;
    vigil::WriteFileAtomic(d / "config.yaml", config::ToYaml(copy));
    return FakeMetrics(c);
  };
}

}  // namespace vigil::experiments::testing
