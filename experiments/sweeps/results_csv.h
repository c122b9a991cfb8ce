// results.csv and timing.csv of a sweep: one row per run each, in plan order, streamed to disk as results
// arrive.
//
// results.csv columns: id, one column per axis (its setting's label), method, seed, status, failure_reason,
// the ATE statistics, the relative errors per distance (mean translation [m], mean yaw [deg] and the number
// of sub-trajectories), detection statistics, estimator resets, NEES means and (appended later, so that
// readers by position keep working) the coverage. Values come from the run's metrics.json
// only and none depends on timing, so the file is the same byte for byte whether runs were executed now or
// read back (--resume), with any -j, in shards, on any machine; a value a run does not have (a failed run's
// errors) is left empty.
// timing.csv: `#id,simulate_s,templates_s,detect_s,estimate_s,evaluate_s,total_s,external_process_s`, the
// wall times of each run's stages (metrics.json "wall_time_s"; the last, the external estimator's process,
// "external.wall_time_s.process", empty for vigil's own), which differ from one execution to the next.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/sweeps/sweep_spec.h"

namespace vigil::experiments {

class ResultsCsvWriter {
 public:
  // Starts DIR/results.csv and DIR/timing.csv as staging files (they appear only at Commit()).
  ResultsCsvWriter(const std::filesystem::path& sweep_dir, const SweepSpec& spec,
                   std::vector<double> distances_m);
  ~ResultsCsvWriter();
  ResultsCsvWriter(const ResultsCsvWriter&) = delete;
  ResultsCsvWriter& operator=(const ResultsCsvWriter&) = delete;

  void Add(const SweepRunRef& run, const SweepCell& cell, const nlohmann::json& metrics);
  // Flushes and renames both into place.
  void Commit();

  std::string Header() const;
  std::string Row(const SweepRunRef& run, const SweepCell& cell, const nlohmann::json& metrics) const;
  static std::string TimingHeader();
  static std::string TimingRow(const SweepRunRef& run, const nlohmann::json& metrics);

 private:
  // One file streamed into its staging name, renamed at Commit().
  struct Stream {
    std::filesystem::path final, temp;
    std::ofstream out;
    void Open(const std::filesystem::path& path, const std::string& header);
    void Commit();
    void Abandon();
  };

  const SweepSpec& spec_;
  std::vector<double> distances_m_;
  Stream results_, timing_;
  bool committed_ = false;
};

}  // namespace vigil::experiments
