// Synthetic run and sweep directories (docs/formats.md) for the figure tests and the rendering benchmark.
//
// Ground truth comes from the simulator; the "estimate" is the ground truth seen in another frame (a yaw and
// a translation, which the display alignment must undo) plus a drift that grows with the glitch mean and
// shrinks with the method (original > trunc > dtw); metrics.json holds matching made-up statistics.
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/dataset.h"
#include "core/output.h"
#include "core/random.h"
#include "detectors/detector.h"
#include "experiments/runs/imu_axis_record.h"
#include "experiments/runs/run_config.h"
#include "sim/simulator.h"

namespace vigil::plots::testing {

struct SyntheticSetting {
  bool enabled = true;
  double mean = 0.0, std = 1.0;
};

inline experiments::RunConfig SyntheticConfig(const SyntheticSetting& setting,
                                              detectors::DetectorType detector, uint64_t seed,
                                              double duration_s) {
  experiments::RunConfig config;
  config.seed = seed;
  config.sim.duration_s = duration_s;
  config.sim.glitch.enabled = setting.enabled;
  config.sim.glitch.mean = setting.mean;
  config.sim.glitch.std = setting.std;
  config.sim.glitch.rate = 0.01;
  config.detector.type = detector;
  return config;
}

inline nlohmann::json Stats(double mean, double spread) {
  return {{"rmse", mean * 1.1},
          {"mean", mean},
          {"median", mean * 0.95},
          {"std", spread},
          {"min", mean * 0.3},
          {"max", mean * 2.0 + spread},
          {"n", 50}};
}

// Writes `dir` (created) as a run directory of `config`; `data` is a simulation of a config with the same
// trajectory and duration (shared between runs to keep tests fast). `failed` writes a failed run;
// `with_figure_data` false leaves out landmarks.csv and imu_axis.csv (a run of an older vigil).
inline void WriteSyntheticRun(const std::filesystem::path& dir, experiments::RunConfig config,
                              const Dataset& data, bool failed = false, bool with_figure_data = true) {
  std::filesystem::create_directories(dir);
  WriteFileAtomic(dir / "config.yaml", config::ToYaml(config));
  const double method_factor = config.detector.type == detectors::DetectorType::kNone        ? 1.0
                               : config.detector.type == detectors::DetectorType::kThreshold ? 0.6
                                                                                             : 0.3;
  const double severity =
      (config.sim.glitch.enabled ? 0.2 + 0.1 * std::abs(config.sim.glitch.mean) : 0.05) * method_factor;
  Rng rng(config.seed, "synthetic_run");
  const double jitter = 1.0 + 0.2 * rng.Normal();
  Trajectory gt, est;
  const Eigen::AngleAxisd yaw(0.4, Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d shift(3.0, -2.0, 0.5);
  const int64_t t0 = data.groundtruth.front().t_ns;
  for (const NavState& s : data.groundtruth) {
    if ((s.t_ns - t0) % 50'000'000 != 0) continue;  // 20 Hz camera frames
    gt.push_back({s.t_ns, s.p_W, s.q_WB});
    const double t = NsToS(s.t_ns - t0);
    if (t < 1.0) continue;  // initialization
    const Eigen::Vector3d drift(severity * jitter * t * 0.1, severity * std::sin(t), 0.05 * severity * t);
    est.push_back({s.t_ns, yaw * (s.p_W + drift) + shift, Eigen::Quaterniond(yaw) * s.q_WB});
  }
  WriteFileAtomic(dir / "stamped_groundtruth.txt", TumTrajectory(gt));
  WriteFileAtomic(dir / "stamped_traj_estimate.txt", TumTrajectory(est));
  nlohmann::json metrics = {{"status", failed ? "failed" : "ok"},
                            {"failure_reason", failed ? "estimator diverged" : ""},
                            {"seed", config.seed},
                            {"duration_s", config.sim.duration_s}};
  if (!failed) {
    metrics["ate"] = {{"align", "posyaw"},
                      {"trans_m", Stats(severity * jitter, 0.1 * severity)},
                      {"rot_deg", Stats(2.0 * severity * jitter, 0.3 * severity)}};
    nlohmann::json relative = nlohmann::json::array();
    for (double d : config.evaluation.distances_m) {
      relative.push_back({{"distance_m", d},
                          {"trans_m", Stats(severity * jitter * d / 20.0, 0.02 * d * severity)},
                          {"yaw_deg", Stats(severity * jitter * d / 10.0, 0.05 * d * severity)}});
    }
    metrics["relative"] = relative;
  }
  WriteFileAtomic(dir / "metrics.json", metrics.dump(2));
  // Flags: the glitched samples of `data` (none without a detector); mitigation: their clean values.
  std::vector<uint8_t> flagged(data.imu.size(), 0);
  ImuStream mitigated = data.imu;
  if (config.detector.type != detectors::DetectorType::kNone) {
    std::size_t g = 0;
    for (std::size_t i = 0; i < data.imu.size(); ++i) {
      while (g < data.glitches.size() && data.glitches[g].t_ns <= data.imu[i].t_ns)
        flagged[i] |= data.glitches[g++].t_ns == data.imu[i].t_ns;
      if (flagged[i]) mitigated[i] = data.imu_clean[i];
    }
    WriteFileAtomic(dir / "detections.csv", detectors::DetectionsCsv(data.imu, flagged));
  }
  if (with_figure_data) {
    WriteFileAtomic(dir / dataset_files::kLandmarks, LandmarksCsv(data.landmarks));
    WriteFileAtomic(dir / experiments::kImuAxisFile,
                    experiments::ImuAxisCsv(experiments::MakeImuAxisRecord(
                        config.sim.glitch.axes.empty() ? ImuAxis::kAz : config.sim.glitch.axes.front(),
                        data.imu, &data.imu_clean, mitigated, flagged)));
  }
}

// A sweep directory: every setting x {none, threshold, dtw} x seeds 1..n; the run of the last seed of
// (first setting, none) is written as failed. Run ids are opaque on purpose (grouping must use config.yaml).
inline void WriteSyntheticSweep(const std::filesystem::path& dir,
                                const std::vector<SyntheticSetting>& settings, int seeds, double duration_s) {
  std::filesystem::create_directories(dir / "runs");
  WriteFileAtomic(dir / "sweep.yaml", "# synthetic sweep for tests\n");
  int index = 0;
  for (std::size_t s = 0; s < settings.size(); ++s) {
    const experiments::RunConfig base =
        SyntheticConfig(settings[s], detectors::DetectorType::kNone, 1, duration_s);
    const Dataset data = sim::Simulate(base.sim, base.seed);
    for (auto detector : {detectors::DetectorType::kNone, detectors::DetectorType::kThreshold,
                          detectors::DetectorType::kDtw}) {
      for (int seed = 1; seed <= seeds; ++seed) {
        char id[32];
        std::snprintf(id, sizeof id, "r%03d", index++);
        const bool failed =
            s == 0 && detector == detectors::DetectorType::kNone && seed == seeds && seeds > 1;
        WriteSyntheticRun(dir / "runs" / id, SyntheticConfig(settings[s], detector, seed, duration_s), data,
                          failed);
      }
    }
  }
}

}  // namespace vigil::plots::testing
