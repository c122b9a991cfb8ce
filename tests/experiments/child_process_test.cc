#include "experiments/child_process.h"

#include <signal.h>

#include <chrono>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/output.h"
#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
namespace fs = std::filesystem;
using vigil::testing::TempDir;

ChildProcessOptions FakeEstimator(const TempDir& tmp, const std::string& mode, double timeout_s = 30.0) {
  ChildProcessOptions o;
  o.program = VIGIL_FAKE_ESTIMATOR;
  o.argv = {o.program, mode, tmp.path().string(), tmp.path().string()};
  o.working_dir = tmp.path();
  o.stdout_path = tmp.path() / "stdout.txt";
  o.stderr_path = tmp.path() / "stderr.txt";
  o.timeout_s = timeout_s;
  return o;
}

// True once `pid` is gone or a zombie (within `wait`): killed, whoever reaps it.
bool EndsWithin(pid_t pid, std::chrono::milliseconds wait) {
  const auto deadline = std::chrono::steady_clock::now() + wait;
  while (std::chrono::steady_clock::now() < deadline) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line)) return true;
    const std::size_t paren = line.rfind(')');
    if (paren != std::string::npos && paren + 2 < line.size() && line[paren + 2] == 'Z') return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(ChildProcess, ReportsTheExitStatusAndCapturesStdout) {
  TempDir tmp;
  const ChildProcessResult r = RunChildProcess(FakeEstimator(tmp, "exit3"));
  EXPECT_EQ(r.outcome, ChildProcessResult::Outcome::kExited);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_FALSE(r.succeeded());
  EXPECT_EQ(r.Describe(30), "exit status 3");
  EXPECT_EQ(ReadFile(tmp.path() / "stdout.txt"), "fake estimator: exit3\n");
}

TEST(ChildProcess, SucceedsOnExitZero) {
  TempDir tmp;
  const ChildProcessResult r = RunChildProcess(FakeEstimator(tmp, "none"));
  EXPECT_TRUE(r.succeeded());
  EXPECT_GE(r.wall_s, 0.0);
}

TEST(ChildProcess, ReportsASignal) {
  TempDir tmp;
  const ChildProcessResult r = RunChildProcess(FakeEstimator(tmp, "signal"));
  EXPECT_EQ(r.outcome, ChildProcessResult::Outcome::kSignaled);
  EXPECT_EQ(r.signal, SIGKILL);
  EXPECT_NE(r.Describe(30).find("signal 9"), std::string::npos);
}

TEST(ChildProcess, TimeoutKillsTheWholeProcessGroup) {
  TempDir tmp;
  const auto start = std::chrono::steady_clock::now();
  const ChildProcessResult r = RunChildProcess(FakeEstimator(tmp, "sleep", 0.5));
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.outcome, ChildProcessResult::Outcome::kTimedOut);
  EXPECT_GE(elapsed, 0.5);
  EXPECT_LT(elapsed, 20.0);  // not the child's 60 s
  EXPECT_NE(r.Describe(0.5).find("timed out after 0.5 s"), std::string::npos);
  // The grandchild it started was in its group: killed too.
  std::ifstream pid_file(tmp.path() / "grandchild.pid");
  pid_t grandchild = 0;
  ASSERT_TRUE(pid_file >> grandchild);
  EXPECT_TRUE(EndsWithin(grandchild, std::chrono::milliseconds(5000)));
}

TEST(ChildProcess, AProgramThatCannotStartIsReported) {
  TempDir tmp;
  ChildProcessOptions o = FakeEstimator(tmp, "good");
  o.program = (tmp.path() / "no_such_program").string();
  const ChildProcessResult r = RunChildProcess(o);
  EXPECT_EQ(r.outcome, ChildProcessResult::Outcome::kNotStarted);
  EXPECT_NE(r.Describe(30).find("could not start"), std::string::npos);
}

}  // namespace
}  // namespace vigil::experiments
