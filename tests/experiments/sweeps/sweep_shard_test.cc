#include "experiments/sweeps/sweep_shard.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"
#include "tests/experiments/sweeps/sweep_test_util.h"

namespace vigil::experiments {
namespace {
using testing::WriteSmallSweep;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

TEST(SweepShard, ShardsPartitionThePlanEveryNthRun) {
  TempDir dir;
  const SweepSpec spec = LoadSweepSpec(WriteSmallSweep(dir, "  trunc: threshold\n  original: none\n"));
  const std::vector<SweepRunRef> runs = EnumerateRuns(spec, EnumerateCells(spec));  // 12 runs
  for (std::size_t n : {1u, 2u, 3u, 5u, 12u, 13u}) {
    std::vector<int> owner(runs.size(), -1);
    for (std::size_t i = 0; i < n; ++i) {
      const SweepShard shard = ParseShard(std::to_string(i) + "/" + std::to_string(n));
      std::size_t previous = 0;
      for (const SweepRunRef& run : ShardRuns(runs, shard)) {
        EXPECT_EQ(owner[run.index], -1) << "run " << run.index << " in two shards";
        owner[run.index] = static_cast<int>(i);
        EXPECT_EQ(run.index % n, i);
        EXPECT_TRUE(previous == 0 || run.index > previous);  // plan order
        previous = run.index;
      }
    }
    for (std::size_t r = 0; r < runs.size(); ++r) EXPECT_GE(owner[r], 0) << "run " << r << " in no shard";
  }
  EXPECT_EQ(ParseShard("2/3").Label(), "2/3");
  EXPECT_TRUE(ParseShard("0/1").whole());
}

TEST(SweepShard, BadShardsAreRefused) {
  EXPECT_NE(InputErrorOf([] { ParseShard("3/3"); }).find("must be below N"), std::string::npos);
  EXPECT_NE(InputErrorOf([] { ParseShard("0/0"); }).find("at least 1"), std::string::npos);
  for (const char* bad : {"", "1", "-1/3", "1/-3", "a/3", "1/3/4", "1/", "/3", "1 /3", "99999999999/1"})
    EXPECT_NE(InputErrorOf([&] { ParseShard(bad); }).find("expected I/N"), std::string::npos) << bad;
}

}  // namespace
}  // namespace vigil::experiments
