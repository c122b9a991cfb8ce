// A Monte Carlo sweep: a grid of run configurations (axes x methods) times seeds.
//
// The sweep file (YAML; configs/paper_sweep.yaml is the paper's grid):
//
//   base: paper.yaml                 # run configuration every run starts from (relative to this file)
//   set: {duration_s: 20, glitch.enabled: true}   # overrides applied to every run (key paths or mappings)
//   axes:                            # the grid, in this order; each axis is a config key path with either
//     glitch:                        #   named settings: name -> keys relative to the axis key, or
//       noise_0_1: {mean: 0, std: 1}
//       noise_50_10: {mean: 50, std: 10}
//     camera.pixel_noise_px: [0, 1]  #   a list of values of that key
//   methods:                         # name -> detector settings (keys relative to `detector`); a scalar is
//     trunc: threshold               #   shorthand for {type: <scalar>}
//     dtw: {type: dtw}
//     trunc_gate: {type: threshold, estimator.mitigation.gating.enabled: true}  # keys under `estimator.`
//                                    #   set the estimator: in-estimator mitigation per method
//   seeds: {count: 10, first: 1}     # or an explicit list [1, 2, 5]
//   template_seed: 1000              # DTW templates: glitch-free simulation with this seed (not a run seed)
//   write_trajectories: true         # keep stamped_*.txt / detections.csv in every run directory
//   write_figure_data: true          # keep landmarks.csv / imu_axis.csv (what figures 1, 2, 5 draw)
//   table_methods: [trunc, dtw]      # methods (in order) of tables 2-4 (default: every method)
//
// A cell is one combination of axis settings and a method; a run is a cell and a seed. Run ids are readable
// and stable: the axis labels, the method and the seed joined by '-', e.g. "noise_50_10-dtw-s003" (a list
// value gets the label "<last key component>_<value>", e.g. "pixel_noise_px_1"). Overrides apply in the order
// base < set < axes (in order) < method < seed, and every value is typed by the run configuration's schema:
// errors name the sweep file and line.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "experiments/runs/run_config.h"

namespace vigil::experiments {

// One `key.path: value` override, with the sweep-file line it came from (for errors).
struct SweepOverride {
  std::string key;  // full key path from the run configuration's top level
  YAML::Node value;
  int line = 0;
};

// One setting of an axis or a method: a label and the overrides it stands for.
struct SweepSetting {
  std::string label;
  std::vector<SweepOverride> overrides;
};

struct SweepAxis {
  std::string key;     // the axis' config key path, also its column name in results.csv
  bool named = false;  // named settings (keys relative to `key`) rather than a list of values of `key`
  std::vector<SweepSetting> settings;
};

struct SweepSpec {
  std::string path;            // the sweep file
  std::filesystem::path base;  // absolute path of the base run configuration
  std::vector<SweepOverride> set;
  std::vector<SweepAxis> axes;
  std::vector<SweepSetting> methods;
  std::vector<uint64_t> seeds;
  uint64_t template_seed = 1000;
  bool write_trajectories = true;
  bool write_figure_data = true;
  std::vector<std::string> table_methods;  // never empty after loading

  std::size_t cell_count() const;  // product of the axis sizes x methods
  std::size_t run_count() const { return cell_count() * seeds.size(); }
};

// Most seeds a sweep may have (checked before anything is allocated or written), and most runs in all.
inline constexpr uint64_t kMaxSweepSeeds = 100000;
inline constexpr uint64_t kMaxSweepRuns = 1000000;

// Reads and checks a sweep file; InputError "file:line: key: reason".
SweepSpec LoadSweepSpec(const std::string& path);

// Replaces the seeds by `count` consecutive ones from the first (`vigil paper --seeds N`); InputError when
// they would include the template seed.
void SetSeedCount(SweepSpec* spec, uint64_t count);

// The resolved sweep file (absolute base path, explicit seed list): written as DIR/sweep.yaml, and read back
// by LoadSweepSpec to give the same spec (so `vigil tables DIR` and `--resume` work from the directory).
std::string ResolvedSweepYaml(const SweepSpec& spec);

// One cell of the grid: which setting of every axis, and which method.
struct SweepCell {
  std::vector<int> setting;  // index into spec.axes[a].settings
  int method = 0;            // index into spec.methods
};

// Cells in grid order (the first axis varies slowest, the method fastest).
std::vector<SweepCell> EnumerateCells(const SweepSpec& spec);

// "noise_50_10" (axis labels joined by '-'; "all" with no axes): the column of a cell in the tables.
std::string CellGroupLabel(const SweepSpec& spec, const SweepCell& cell);

// "noise_50_10-dtw-s003".
std::string RunId(const SweepSpec& spec, const SweepCell& cell, uint64_t seed);

// Throws InputError for `message` ("key: reason") about a cell's configuration, naming the sweep-file line
// (else the base file's line) that set a key it is about (experiments/runs/run_config.h KeysOfConfigError).
[[noreturn]] void ThrowCellError(const SweepSpec& spec, const SweepCell& cell, const std::string& message);

// The run configuration of a cell (seed not yet applied: the base's). InputError naming the sweep file line.
RunConfig ResolveCellConfig(const SweepSpec& spec, const SweepCell& cell);

// One run of the sweep, in plan order: run index r is cell r / seeds.size(), seed seeds[r % seeds.size()].
struct SweepRunRef {
  std::size_t index = 0;
  std::size_t cell = 0;
  uint64_t seed = 0;
  std::string id;
};
std::vector<SweepRunRef> EnumerateRuns(const SweepSpec& spec, const std::vector<SweepCell>& cells);

// The distances of the relative errors of a sweep (its first cell's evaluation.distances_m).
std::vector<double> SweepDistances(const SweepSpec& spec);

}  // namespace vigil::experiments
