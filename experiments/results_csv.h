// results.csv of a sweep: one row per run, in plan order, streamed to disk as results arrive.
//
// Columns: id, one column per axis (its setting's label), method, seed, status, failure_reason, the ATE
// statistics, the relative errors per distance (mean translation [m], mean yaw [deg] and the number of
// sub-trajectories), detection statistics, estimator resets and the run's wall time. Values come from the
// run's metrics.json only, so the file is the same whether runs were executed now or read back (--resume);
// a value a run does not have (a failed run's errors) is left empty.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/sweep_spec.h"

namespace vigil::experiments {

class ResultsCsvWriter {
 public:
  // Starts DIR/results.csv.tmp-<pid> (results.csv appears only at Commit()).
  ResultsCsvWriter(const std::filesystem::path& sweep_dir, const SweepSpec& spec,
                   std::vector<double> distances_m);
  ~ResultsCsvWriter();
  ResultsCsvWriter(const ResultsCsvWriter&) = delete;
  ResultsCsvWriter& operator=(const ResultsCsvWriter&) = delete;

  void Add(const SweepRunRef& run, const SweepCell& cell, const nlohmann::json& metrics);
  // Flushes and renames into DIR/results.csv.
  void Commit();

  std::string Header() const;
  std::string Row(const SweepRunRef& run, const SweepCell& cell, const nlohmann::json& metrics) const;

 private:
  const SweepSpec& spec_;
  std::vector<double> distances_m_;
  std::filesystem::path final_, temp_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace vigil::experiments
