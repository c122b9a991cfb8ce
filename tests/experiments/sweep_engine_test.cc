#include "experiments/sweep_engine.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <mutex>
#include <set>

#include <gtest/gtest.h>

#include "core/output.h"
#include "experiments/progress.h"
#include "experiments/sweep_runner.h"
#include "sim/simulator.h"
#include "tests/core/test_util.h"
#include "tests/experiments/sweep_test_util.h"

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using testing::FakeMetrics;
using testing::SleepMs;
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

TEST(SweepEngine, RunsExecuteInParallel) {
  TempDir dir;
  std::atomic<int> running{0}, most{0};
  SweepEngineOptions options;
  options.threads = 2;
  ExecuteSweep(
      dir.path(), Ids(8),
      [&](std::size_t, const fs::path&) {
        const int now = ++running;
        int seen = most.load();
        while (now > seen && !most.compare_exchange_weak(seen, now)) {
        }
        SleepMs(30);
        --running;
        return nlohmann::json{{"status", "ok"}};
      },
      {}, options);
  EXPECT_EQ(most.load(), 2);
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
  fs::create_directories(dir.path() / "runs" / "run5.tmp-99999");  // left by a killed sweep
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
  EXPECT_FALSE(fs::exists(dir.path() / "runs" / "run5.tmp-99999"));

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

constexpr const char* kHelperEnv = "VIGIL_SWEEP_KILL_HELPER_DIR";

RunExecutor SlowFakeExecutor(int sleep_ms) {
  return [sleep_ms](const RunConfig& c, const RunOptions&, const fs::path& d) {
    SleepMs(sleep_ms);
    vigil::WriteFileAtomic(d / "config.yaml", config::ToYaml(const_cast<RunConfig&>(c)));
    return FakeMetrics(c);
  };
}

constexpr const char* kMethods = "  trunc: threshold\n  original: none\n  hampel: hampel\n";

// Not a test of its own: the process that ResumeAfterKillGivesTheSameResults starts and kills.
TEST(SweepKillHelper, RunSlowSweep) {
  const char* dir = std::getenv(kHelperEnv);
  if (!dir) GTEST_SKIP() << "helper process of SweepRunner.ResumeAfterKillGivesTheSameResults";
  SweepRunOptions options;
  options.threads = 2;
  RunSweep(LoadSweepSpec((fs::path(dir) / "sweep.yaml").string()), fs::path(dir) / "out", options,
           SlowFakeExecutor(40));
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
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::setenv(kHelperEnv, dir.path().c_str(), 1);
    const std::string filter = "--gtest_filter=SweepKillHelper.RunSlowSweep";
    char exe[] = "/proc/self/exe";
    char* argv[] = {exe, const_cast<char*>(filter.c_str()), nullptr};
    ::execv(exe, argv);
    ::_exit(127);
  }
  const fs::path out = dir.path() / "out";
  for (int i = 0; i < 1000 && CommittedRuns(out / "runs") < 8; ++i) SleepMs(5);
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  const std::size_t committed = CommittedRuns(out / "runs");
  ASSERT_GE(committed, 8u);
  ASSERT_LT(committed, 30u) << "the helper finished before it was killed";
  EXPECT_FALSE(fs::exists(out / "results.csv"));

  const SweepSpec spec = LoadSweepSpec(sweep);
  SweepRunOptions resume;
  resume.threads = 2;
  resume.resume = true;
  const SweepOutcome o = RunSweep(spec, out, resume, SlowFakeExecutor(0));
  EXPECT_EQ(o.resumed + o.executed, 30u);
  EXPECT_EQ(o.resumed, committed);

  SweepRunOptions straight;
  straight.threads = 1;
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
  options.write_tables = false;
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

}  // namespace
}  // namespace vigil::experiments
