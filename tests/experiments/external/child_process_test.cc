#include "experiments/external/child_process.h"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <fstream>

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

// The child sleeps 60 s with a grandchild in its group: at the timeout both are killed, and reaped before the
// call returns (/proc/PID is absent then: no waiting, no timing margin).
TEST(ChildProcess, TimeoutKillsTheWholeProcessGroup) {
  TempDir tmp;
  const ChildProcessResult r = RunChildProcess(FakeEstimator(tmp, "sleep", 3.0));
  EXPECT_EQ(r.outcome, ChildProcessResult::Outcome::kTimedOut);
  EXPECT_NE(r.Describe(3.0).find("timed out after 3 s"), std::string::npos);
  std::ifstream pid_file(tmp.path() / "grandchild.pid");
  pid_t grandchild = 0;
  ASSERT_TRUE(pid_file >> grandchild);
  EXPECT_FALSE(fs::exists("/proc/" + std::to_string(grandchild)));
}

// A grandchild that leaves the group and the session (setsid) is still the run's: once the call returns it
// is gone, killed and reaped (the supervisor is its subreaper). No waiting: /proc/PID is absent at return.
TEST(ChildProcess, NothingTheProgramStartedOutlivesTheCall) {
  TempDir tmp;
  const ChildProcessResult r = RunChildProcess(FakeEstimator(tmp, "setsid"));
  EXPECT_TRUE(r.succeeded()) << r.Describe(30) << " " << r.error;
  std::ifstream pid_file(tmp.path() / "grandchild.pid");
  pid_t grandchild = 0;
  ASSERT_TRUE(pid_file >> grandchild);
  const bool alive = fs::exists("/proc/" + std::to_string(grandchild));
  EXPECT_FALSE(alive) << "grandchild " << grandchild << " outlived the run";
  if (alive) ::kill(grandchild, SIGKILL);
}

// The wait never ends before its deadline: poll(2)'s milliseconds are rounded up, never truncated (a
// truncated 0.9 ms left ended the wait at once; the timeout of 0.5 s fired after 0.49992 s).
TEST(ChildProcess, TheWaitIsRoundedUpToWholeMilliseconds) {
  using std::chrono::microseconds;
  using std::chrono::milliseconds;
  EXPECT_EQ(PollTimeoutMs(microseconds(0)), 0);
  EXPECT_EQ(PollTimeoutMs(microseconds(-5)), 0);
  EXPECT_EQ(PollTimeoutMs(microseconds(1)), 1);
  EXPECT_EQ(PollTimeoutMs(microseconds(900)), 1);
  EXPECT_EQ(PollTimeoutMs(microseconds(499900)), 500);
  EXPECT_EQ(PollTimeoutMs(milliseconds(500)), 500);
  EXPECT_EQ(PollTimeoutMs(std::chrono::hours(1000)), 1 << 30);
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
