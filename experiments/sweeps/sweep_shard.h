// One shard of a sweep's plan, for running a sweep as several processes or machines (a Slurm job array).
//
// Shard I of N (0 <= I < N) holds the runs whose plan index r satisfies r % N == I: a fixed partition of the
// plan that depends on nothing but I and N (not on -j, the machine or what is already on disk). Taking every
// N-th run (rather than N blocks) spreads each cell, and so the cost of slow methods, over every shard.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "experiments/sweeps/sweep_spec.h"

namespace vigil::experiments {

struct SweepShard {
  std::size_t index = 0;
  std::size_t count = 1;  // 1: the whole sweep

  bool whole() const { return count == 1; }
  bool Contains(std::size_t run_index) const { return run_index % count == index; }
  std::string Label() const;  // "1/3"
};

// Parses "I/N"; InputError "--shard: ..." unless 0 <= I < N and N >= 1.
SweepShard ParseShard(const std::string& text);

// The runs of `shard`, in plan order.
std::vector<SweepRunRef> ShardRuns(const std::vector<SweepRunRef>& runs, const SweepShard& shard);

}  // namespace vigil::experiments
