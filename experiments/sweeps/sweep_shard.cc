#include "experiments/sweeps/sweep_shard.h"

#include <algorithm>

#include "core/error.h"

namespace vigil::experiments {
namespace {
// A non-negative decimal integer, or -1.
long long ParseCount(const std::string& s) {
  if (s.empty() || s.size() > 9 ||
      !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return -1;
  return std::stoll(s);
}
}  // namespace

std::string SweepShard::Label() const { return std::to_string(index) + "/" + std::to_string(count); }

SweepShard ParseShard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const long long i = slash == std::string::npos ? -1 : ParseCount(text.substr(0, slash));
  const long long n = slash == std::string::npos ? -1 : ParseCount(text.substr(slash + 1));
  if (i < 0 || n < 0)
    throw InputError("--shard " + text + ": expected I/N with integers 0 <= I < N (e.g. 0/4)");
  if (n < 1) throw InputError("--shard " + text + ": the shard count N must be at least 1");
  if (i >= n) throw InputError("--shard " + text + ": the shard index I must be below N (0 <= I < N)");
  SweepShard shard;
  shard.index = static_cast<std::size_t>(i);
  shard.count = static_cast<std::size_t>(n);
  return shard;
}

std::vector<SweepRunRef> ShardRuns(const std::vector<SweepRunRef>& runs, const SweepShard& shard) {
  std::vector<SweepRunRef> out;
  for (const SweepRunRef& run : runs)
    if (shard.Contains(run.index)) out.push_back(run);
  return out;
}

}  // namespace vigil::experiments
