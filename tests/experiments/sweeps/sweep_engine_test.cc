#include "experiments/sweeps/sweep_engine.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <set>

#include <gtest/gtest.h>

#include "core/output.h"
#include "core/staging.h"
#include "experiments/sweeps/progress.h"
#include "experiments/sweeps/sweep_lock.h"
#include "experiments/sweeps/sweep_runner.h"
#include "report/tables.h"
#include "sim/simulator.h"
#include "tests/core/test_util.h"
#include "tests/experiments/sweeps/sweep_test_util.h"

extern char** environ;

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using testing::FakeMetrics;
using testing::SleepMs;
using testing::SlowFakeExecutor;
using testing::WriteSmallSweep;
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

std::vector<std::string> Ids(int n) {
  std::vector<std::string> ids;
  for (int i = 0; i < n; ++i) ids.push_back("run" + std::to_string(i));
  return ids;
}

// A run whose result depends on its index only, and whose duration varies (so threads finish out of order).
nlohmann::json IndexRun(std::size_t index, const fs::path& dir) {
  SleepMs(static_cast<int>((index * 7) % 5));
  vigil::WriteFileAtomic(dir / "note.txt", "run " + std::to_string(index) + "\n");
  Rng rng(index, "engine_test");
  return {{"status", "ok"}, {"value", rng.Normal()}};
}

TEST(SweepEngine, ResultsArriveInPlanOrderAndAreTheSameForAnyThreadCount) {
  TempDir dir;
  std::vector<std::string> texts;
  for (int threads : {1, 4}) {
    const fs::path out = dir.path() / ("j" + std::to_string(threads));
    PrepareSweepDirectory(out, false, false);
    std::vector<std::size_t> order;
    std::string text;
    SweepEngineOptions options;
    options.threads = threads;
    const SweepOutcome o = ExecuteSweep(
        out, Ids(40), IndexRun,
        [&](std::size_t i, const nlohmann::json& m) {
          order.push_back(i);
          text += std::to_string(i) + " " + m.dump() + "\n";
        },
        options);
    EXPECT_EQ(o.total, 40u);
    EXPECT_EQ(o.executed, 40u);
    EXPECT_EQ(o.failed, 0u);
    for (std::size_t i = 0; i < order.size(); ++i) ASSERT_EQ(order[i], i);
    EXPECT_EQ(vigil::ReadFile(out / "runs" / "run7" / "note.txt"), "run 7\n");
    texts.push_back(text);
  }
  EXPECT_EQ(texts[0], texts[1]);
}

// A barrier for two: the first run to arrive waits until a second one arrives, which can only happen when
// two runs execute at the same time. A wait that times out counts as a failure (no run is left stuck).
class PairBarrier {
 public:
  // False when no partner came within the timeout.
  bool ArriveAndWait(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    const std::size_t generation = generation_;
    if (++waiting_ == 2) {
      waiting_ = 0;
      ++generation_;
      released_.notify_all();
      return true;
    }
    if (released_.wait_for(lock, timeout, [&] { return generation_ != generation; })) return true;
    waiting_ = 0;  // give up this generation: the next arrival starts a new pair
    ++generation_;
    return false;
  }

 private:
  std::mutex mutex_;
  std::condition_variable released_;
  std::size_t waiting_ = 0, generation_ = 0;
};

TEST(SweepEngine, RunsExecuteInParallel) {
  TempDir dir;
  PairBarrier barrier;
  std::atomic<int> running{0}, most{0}, timeouts{0};
  SweepEngineOptions options;
  options.threads = 2;
  ExecuteSweep(
      dir.path(), Ids(8),
      [&](std::size_t, const fs::path&) {
        const int now = ++running;
        int seen = most.load();
        while (now > seen && !most.compare_exchange_weak(seen, now)) {
        }
        if (!barrier.ArriveAndWait(std::chrono::seconds(20))) ++timeouts;
        --running;
        return nlohmann::json{{"status", "ok"}};
      },
      {}, options);
  EXPECT_EQ(timeouts.load(), 0) << "a run waited in vain for a second one running at the same time";
  EXPECT_EQ(most.load(), 2);  // never more runs at once than threads
}

TEST(SweepEngine, FailuresAreRecordedAndTheSweepGoesOn) {
  TempDir dir;
  SweepEngineOptions options;
  options.threads = 2;
  std::vector<std::string> statuses;
  const SweepOutcome o = ExecuteSweep(
      dir.path(), Ids(6),
      [](std::size_t i, const fs::path&) -> nlohmann::json {
        if (i == 2) throw std::runtime_error("estimator exploded");
        if (i == 4) return {{"status", "failed"}, {"failure_reason", "diverged: |b_a| > 2.5"}};
        return {{"status", "ok"}};
      },
      [&](std::size_t, const nlohmann::json& m) { statuses.push_back(m["status"]); }, options);
  EXPECT_EQ(o.failed, 2u);
  EXPECT_EQ(statuses, (std::vector<std::string>{"ok", "ok", "failed", "ok", "failed", "ok"}));
  const auto m2 = nlohmann::json::parse(vigil::ReadFile(RunMetricsPath(dir.path(), "run2")));
  EXPECT_EQ(m2["failure_reason"], "estimator exploded");
  for (const auto& id : Ids(6)) EXPECT_TRUE(fs::is_regular_file(RunMetricsPath(dir.path(), id))) << id;
}

TEST(SweepEngine, ResumeSkipsFinishedRunsAndCleansStaging) {
  TempDir dir;
  const auto all = Ids(10);
  ExecuteSweep(dir.path(), {all.begin(), all.begin() + 4}, IndexRun, {}, {});
  const pid_t dead = fork();  // a process that has exited: its staging is stale
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  const std::string host = vigil::StagingHost();
  const fs::path stale = dir.path() / "runs" / ("run5.tmp-" + host + "-" + std::to_string(dead));
  const fs::path live = dir.path() / "runs" / ("run6.tmp-" + host + "-1");  // init: alive
  const fs::path remote = dir.path() / "runs" / ("run7.tmp-othernode-" + std::to_string(dead));
  for (const auto& p : {stale, live, remote}) fs::create_directories(p);
  std::atomic<int> calls{0};
  SweepEngineOptions options;
  options.resume = true;
  std::string resumed_text;
  const SweepOutcome o = ExecuteSweep(
      dir.path(), all,
      [&](std::size_t i, const fs::path& d) {
        ++calls;
        return IndexRun(i, d);
      },
      [&](std::size_t, const nlohmann::json& m) { resumed_text += m.dump() + "\n"; }, options);
  EXPECT_EQ(calls.load(), 6);
  EXPECT_EQ(o.resumed, 4u);
  EXPECT_EQ(o.executed, 6u);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));    // a live process is writing it (maybe another shard)
  EXPECT_TRUE(fs::exists(remote));  // another host's: its liveness cannot be known from here

  TempDir fresh_dir;
  std::string fresh_text;
  ExecuteSweep(fresh_dir.path() / "x", all, IndexRun,
               [&](std::size_t, const nlohmann::json& m) { fresh_text += m.dump() + "\n"; }, {});
  EXPECT_EQ(resumed_text, fresh_text);
}

TEST(SweepEngine, OutputDirectoryRules) {
  TempDir dir;
  const fs::path out = dir.path() / "sweep";
  PrepareSweepDirectory(out, false, false);
  dir.File("sweep/results.csv", "old");
  dir.File("sweep/notes.txt", "mine");
  EXPECT_NE(InputErrorOf([&] { PrepareSweepDirectory(out, false, false); }).find("use --resume"),
            std::string::npos);
  EXPECT_NE(InputErrorOf([&] { PrepareSweepDirectory(out, false, true); }).find("not a sweep directory"),
            std::string::npos);  // --force never touches a directory without sweep.yaml
  EXPECT_EQ(ReadFile(out / "results.csv"), "old");
  fs::create_directories(out / "runs" / "a");
  dir.File("sweep/sweep.yaml", "x");
  PrepareSweepDirectory(out, false, true);
  EXPECT_FALSE(fs::exists(out / "runs"));
  EXPECT_FALSE(fs::exists(out / "results.csv"));
  EXPECT_TRUE(fs::exists(out / "notes.txt"));  // not the sweep's: left alone
  dir.File("file", "x");
  EXPECT_NE(
      InputErrorOf([&] { PrepareSweepDirectory(dir.path() / "file", false, true); }).find("not a directory"),
      std::string::npos);
}

TEST(Progress, LineShowsCountsFailuresAndEta) {
  ProgressState s;
  s.total = 40;
  s.done = 12;
  s.resumed = 2;
  s.failed = 1;
  s.elapsed_s = 20.0;  // 10 runs executed in 20 s: 28 left -> 56 s
  EXPECT_EQ(FormatProgressLine(s, 10), "[###.......] 12/40 runs (2 resumed), 1 failed, 20s elapsed, ETA 56s");
  s.done = s.resumed = 2;
  EXPECT_NE(FormatProgressLine(s, 10).find("ETA --"), std::string::npos);
  EXPECT_EQ(FormatDuration(125), "2m05s");
  EXPECT_EQ(FormatDuration(7500), "2h05m");
}

TEST(Progress, BarWritesToItsStreamOnlyWhenEnabled) {
  char* buf = nullptr;
  std::size_t size = 0;
  std::FILE* mem = open_memstream(&buf, &size);
  {
    ProgressBar bar(3, mem);
    bar.Finished(false, true);
    bar.Finished(true, false);
    bar.Finished(false, false);
    EXPECT_EQ(bar.state().failed, 1u);
  }
  std::fclose(mem);
  const std::string text(buf, size);
  std::free(buf);
  EXPECT_NE(text.find("3/3 runs (1 resumed), 1 failed"), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
  ProgressBar silent(3, nullptr);  // no stream: nothing to write to, no crash
  silent.Finished(false, false);
}

// ---------------------------------------------------------------------------------------------------------
// The whole sweep with a fake executor: kill -9 in the middle, resume, and compare with an uninterrupted one.

constexpr const char* kMethods = "  trunc: threshold\n  original: none\n  hampel: hampel\n";

// Starts the sweep helper executable (tests/experiments/sweeps/sweep_helper.cc) with `args`.
pid_t StartHelper(const std::vector<std::string>& args) {
  std::vector<std::string> words = {VIGIL_SWEEP_HELPER};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t child = -1;
  if (::posix_spawn(&child, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  return child;
}

int ExitStatusOf(pid_t child) {
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::size_t CommittedRuns(const fs::path& runs) {
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(runs, ec))
    if (e.path().filename().string().find(".tmp-") == std::string::npos) ++n;
  return n;
}

TEST(SweepRunner, ResumeAfterKillGivesTheSameResults) {
  TempDir dir;
  const std::string sweep = WriteSmallSweep(dir, kMethods, "{count: 5, first: 1}");  // 30 runs
  const fs::path out = dir.path() / "out";
  constexpr std::size_t kKilledInRun = 8;  // the helper kills itself inside its 9th run
  const pid_t child = StartHelper({sweep, out.string(), "--die-at-run", std::to_string(kKilledInRun)});
  ASSERT_GT(child, 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "exit status " << status;
  const std::size_t committed = CommittedRuns(out / "runs");
  ASSERT_EQ(committed, kKilledInRun);
  EXPECT_FALSE(fs::exists(out / "results.csv"));
  std::size_t staged = 0;  // run 8, half-written
  for (const auto& e : fs::directory_iterator(out / "runs"))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) ++staged;
  EXPECT_EQ(staged, 1u);

  const SweepSpec spec = LoadSweepSpec(sweep);
  SweepRunOptions resume;
  resume.threads = 2;
  resume.resume = true;
  resume.write_tables = report::WriteTableFiles;
  const SweepOutcome o = RunSweep(spec, out, resume, SlowFakeExecutor(0));
  EXPECT_EQ(o.resumed + o.executed, 30u);
  EXPECT_EQ(o.resumed, committed);
  // The killed helper's staging (its run directories, results.csv.tmp-<host>-<pid>) is gone.
  for (const auto& e : fs::recursive_directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();

  SweepRunOptions straight;
  straight.threads = 1;
  straight.write_tables = report::WriteTableFiles;
  RunSweep(spec, dir.path() / "straight", straight, SlowFakeExecutor(0));
  const std::string results = vigil::ReadFile(out / "results.csv");
  EXPECT_EQ(results, vigil::ReadFile(dir.path() / "straight" / "results.csv"));
  EXPECT_EQ(std::count(results.begin(), results.end(), '\n'), 31);
  for (const char* f : {"table2.md", "table3.csv", "table4.tex"})
    EXPECT_EQ(vigil::ReadFile(out / f), vigil::ReadFile(dir.path() / "straight" / f)) << f;
}

TEST(SweepRunner, ResumeRefusesADifferentSweep) {
  TempDir dir;
  const std::string sweep = WriteSmallSweep(dir, kMethods, "[1]");
  SweepRunOptions options;
  RunSweep(LoadSweepSpec(sweep), dir.path() / "out", options, SlowFakeExecutor(0));
  const std::string other = WriteSmallSweep(dir, kMethods, "[1, 2]");
  options.resume = true;
  EXPECT_NE(InputErrorOf([&] {
              RunSweep(LoadSweepSpec(other), dir.path() / "out", options, SlowFakeExecutor(0));
            }).find("a different sweep"),
            std::string::npos);
  options.resume = false;
  EXPECT_NE(InputErrorOf([&] {
              RunSweep(LoadSweepSpec(other), dir.path() / "out", options, SlowFakeExecutor(0));
            }).find("not empty"),
            std::string::npos);
}

TEST(SweepRunner, DtwTemplatesAreBuiltOnceFromADisjointSeedAndShared) {
  TempDir dir;
  const SweepSpec spec = LoadSweepSpec(WriteSmallSweep(dir, "  dtw: dtw\n  original: none\n", "[1, 2]"));
  std::mutex mutex;
  std::set<const detectors::TemplateLibrary*> seen;
  std::size_t original_with_templates = 0;
  SweepRunOptions options;
  options.threads = 2;
  RunSweep(spec, dir.path() / "out", options, [&](const RunConfig& c, const RunOptions& o, const fs::path&) {
    std::lock_guard<std::mutex> lock(mutex);
    if (c.detector.type == detectors::DetectorType::kDtw) {
      EXPECT_NE(o.templates, nullptr);
      seen.insert(o.templates);
    } else if (o.templates) {
      ++original_with_templates;
    }
    return FakeMetrics(c);
  });
  // Both glitch settings share the glitch-free scenario: one library.
  EXPECT_EQ(seen.size(), 1u);
  EXPECT_EQ(original_with_templates, 0u);
  const auto cells = EnumerateCells(spec);
  std::vector<RunConfig> configs;
  for (const auto& c : cells) configs.push_back(ResolveCellConfig(spec, c));
  const SweepTemplates t = BuildSweepTemplates(spec, configs, std::vector<bool>(cells.size(), true), 1);
  EXPECT_EQ(t.built, 1u);
  ASSERT_TRUE(t.per_cell[0]);
  EXPECT_EQ(t.per_cell[0]->source, "glitch-free simulation, seed 1000");
  // The library is the one built from the glitch-free simulation with the template seed.
  sim::SimOptions clean = configs[0].sim;
  clean.glitch.enabled = false;
  const auto expected = detectors::BuildTemplates(sim::Simulate(clean, 1000).imu, configs[0].detector.dtw);
  EXPECT_EQ(t.per_cell[0]->values, expected.values);
  EXPECT_EQ(t.per_cell[0]->threshold, expected.threshold);
}

// What a sweep directory holds at its top level and in runs/ (names only).
std::set<std::string> Listing(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    names.insert(fs::relative(e.path(), dir).string());
  return names;
}

TEST(SweepRunner, ConcurrentShardsGiveTheSameResultsAsOneSweep) {
  TempDir dir;
  const std::string sweep = WriteSmallSweep(dir, kMethods, "{count: 5, first: 1}");  // 30 runs
  const fs::path out = dir.path() / "sharded";
  const std::string ready = (dir.path() / "ready-").string();
  const pid_t a = StartHelper({sweep, out.string(), "5", "0/2", ready, "2"});
  const pid_t b = StartHelper({sweep, out.string(), "5", "1/2", ready, "2"});
  ASSERT_GT(a, 0);
  ASSERT_GT(b, 0);
  EXPECT_EQ(ExitStatusOf(a), 0);
  EXPECT_EQ(ExitStatusOf(b), 0);
  // Shards write runs and sweep.yaml only: no shared results.csv, no staging left.
  for (const auto& name : Listing(out))
    EXPECT_TRUE(name == "sweep.yaml" || name == kSweepLockFile || name == "runs" ||
                name.rfind("runs/", 0) == 0)
        << name;
  EXPECT_EQ(CommittedRuns(out / "runs"), 30u);
  report::WriteSweepTables(out);

  SweepRunOptions straight;
  straight.threads = 2;
  straight.write_tables = report::WriteTableFiles;
  const fs::path one = dir.path() / "one";
  RunSweep(LoadSweepSpec(sweep), one, straight, SlowFakeExecutor(0));
  for (const char* f : {"results.csv", "table2.md", "table3.csv", "table4.tex", "summary.md"})
    EXPECT_EQ(vigil::ReadFile(out / f), vigil::ReadFile(one / f)) << f;
}

// Two sweeps into one directory: while one holds the directory (here this test process, holding its lock as
// a running sweep does), another is refused with exit status 2 and writes nothing; once it has ended, the
// directory is free. The shards of one sweep share it. Processes and a kernel lock: no timing involved.
TEST(SweepRunner, ASecondSweepIntoADirectoryInUseIsRefused) {
  TempDir dir;
  const std::string sweep = WriteSmallSweep(dir, kMethods, "[1, 2]");  // 12 runs
  const fs::path out = dir.path() / "out";
  {
    const SweepDirectoryLock running(out, /*exclusive=*/true);
    const pid_t second = StartHelper({sweep, out.string(), "0"});
    ASSERT_GT(second, 0);
    EXPECT_EQ(ExitStatusOf(second), 2);
    const pid_t shard = StartHelper({sweep, out.string(), "0", "0/2"});
    ASSERT_GT(shard, 0);
    EXPECT_EQ(ExitStatusOf(shard), 2);
    EXPECT_EQ(Listing(out), std::set<std::string>{kSweepLockFile});
    EXPECT_EQ(
        InputErrorOf([&] { RunSweep(LoadSweepSpec(sweep), out, SweepRunOptions{}, SlowFakeExecutor(0)); }),
        out.string() + ": another vigil sweep is writing into this directory (it holds " +
            (out / kSweepLockFile).string() +
            "); wait until it ends, or choose another output (only the shards of one sweep may share a "
            "directory)");
  }
  const pid_t after = StartHelper({sweep, out.string(), "0"});
  ASSERT_GT(after, 0);
  EXPECT_EQ(ExitStatusOf(after), 0);
  EXPECT_EQ(CommittedRuns(out / "runs"), 12u);

  const fs::path sharded = dir.path() / "sharded";
  const SweepDirectoryLock other_shard(sharded, /*exclusive=*/false);
  const pid_t whole = StartHelper({sweep, sharded.string(), "0"});
  ASSERT_GT(whole, 0);
  EXPECT_EQ(ExitStatusOf(whole), 2);
  const pid_t shard = StartHelper({sweep, sharded.string(), "0", "1/2"});
  ASSERT_GT(shard, 0);
  EXPECT_EQ(ExitStatusOf(shard), 0);
  EXPECT_EQ(CommittedRuns(sharded / "runs"), 6u);
}

TEST(SweepRunner, ShardsAreResumedAndCheckedAgainstTheDirectorysSweep) {
  TempDir dir;
  const SweepSpec spec = LoadSweepSpec(WriteSmallSweep(dir, kMethods, "[1, 2]"));  // 12 runs
  const fs::path out = dir.path() / "out";
  SweepRunOptions shard;
  shard.shard = ParseShard("0/3");
  const SweepOutcome first = RunSweep(spec, out, shard, SlowFakeExecutor(0));
  EXPECT_EQ(first.total, 4u);
  EXPECT_EQ(first.executed, 4u);
  EXPECT_EQ(CommittedRuns(out / "runs"), 4u);
  // Again without --resume: its runs are there already.
  EXPECT_NE(InputErrorOf([&] { RunSweep(spec, out, shard, SlowFakeExecutor(0)); }).find("use --resume"),
            std::string::npos);
  shard.resume = true;
  EXPECT_EQ(RunSweep(spec, out, shard, SlowFakeExecutor(0)).resumed, 4u);
  // --force would remove the other shards' runs.
  SweepRunOptions force;
  force.shard = ParseShard("1/3");
  force.force = true;
  EXPECT_NE(InputErrorOf([&] { RunSweep(spec, out, force, SlowFakeExecutor(0)); }).find("--force"),
            std::string::npos);
  // A sweep file changed between shards.
  const SweepSpec changed = LoadSweepSpec(WriteSmallSweep(dir, kMethods, "[1, 3]"));
  SweepRunOptions other;
  other.shard = ParseShard("1/3");
  EXPECT_NE(InputErrorOf([&] {
              RunSweep(changed, out, other, SlowFakeExecutor(0));
            }).find("a different sweep was started"),
            std::string::npos);
  EXPECT_EQ(CommittedRuns(out / "runs"), 4u);
  // The other shards of the same sweep complete it; `vigil tables` then equals one whole sweep.
  for (const char* s : {"1/3", "2/3"}) {
    other.shard = ParseShard(s);
    RunSweep(spec, out, other, SlowFakeExecutor(0));
  }
  EXPECT_EQ(report::WriteSweepTables(out).missing, 0u);
  RunSweep(spec, dir.path() / "one", {}, SlowFakeExecutor(0));
  EXPECT_EQ(vigil::ReadFile(out / "results.csv"), vigil::ReadFile(dir.path() / "one" / "results.csv"));
}

TEST(SweepRunner, ResumeRefusesADirectoryThatIsNotASweep) {
  TempDir dir;
  const SweepSpec spec = LoadSweepSpec(WriteSmallSweep(dir, kMethods, "[1]"));
  const fs::path out = dir.path() / "mine";
  fs::create_directories(out);
  dir.File("mine/thesis.tex", "precious");
  SweepRunOptions options;
  options.resume = true;
  EXPECT_NE(InputErrorOf([&] {
              RunSweep(spec, out, options, SlowFakeExecutor(0));
            }).find("not a sweep directory (no sweep.yaml)"),
            std::string::npos);
  EXPECT_EQ(Listing(out), (std::set<std::string>{"thesis.tex"}));
}

TEST(SweepRunner, AnInvalidPlanWritesNothing) {
  TempDir dir;
  WriteSmallSweep(dir, kMethods, "[1]");
  // A configuration beyond the limits, and a template library that cannot be built (k = 500 templates from
  // a 4 s scenario), are refused before the directory is created.
  dir.File("huge.yaml", "base: base.yaml\nset: {duration_s: 1e9}\nmethods: {original: none}\nseeds: [1]\n");
  dir.File("k500.yaml", "base: base.yaml\nmethods: {dtw: {type: dtw, dtw: {templates: 500}}}\nseeds: [1]\n");
  for (const auto& [name, why] : std::vector<std::pair<std::string, std::string>>{
           {"huge.yaml", "huge.yaml:2: duration_s: "},
           {"k500.yaml",
            "k500.yaml:2: detector.dtw.templates: a template library of k = 500 templates needs "
            "k + 1 = 501 clean slices"}}) {
    const std::string file = name;  // a lambda may not capture a structured binding in C++17 (clang)
    const fs::path out = dir.path() / (file + ".out");
    EXPECT_NE(InputErrorOf([&] {
                RunSweep(LoadSweepSpec((dir.path() / file).string()), out, {}, SlowFakeExecutor(0));
              }).find(why),
              std::string::npos)
        << file;
    EXPECT_FALSE(fs::exists(out)) << file;
  }
}

}  // namespace
}  // namespace vigil::experiments
