// Ctrl-C (SIGINT), SIGTERM or SIGHUP while `vigil run` waits for an external estimator: the signal is handed
// on to the estimator, which ends with everything it started, the temporary recording is removed, and vigil
// ends with the same signal. The fake estimator (tests/experiments/external/fake_estimator.cc, mode announce)
// tells the test through a FIFO that it runs: no timing margin, the 60 s poll only keeps a failure from
// hanging.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

extern char** environ;

namespace vigil {
namespace {
namespace fs = std::filesystem;
using testing::TempDir;

// Starts vigil with `args` and `extra_env` added to the environment, every signal at its default.
pid_t StartVigil(const std::vector<std::string>& args, const std::vector<std::string>& extra_env,
                 const fs::path& stderr_path) {
  std::vector<std::string> words = {VIGIL_BINARY};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_words(extra_env);
  for (char** e = environ; *e != nullptr; ++e) env_words.emplace_back(*e);
  std::vector<char*> envp;
  for (std::string& w : env_words) envp.push_back(w.data());
  envp.push_back(nullptr);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t all, none;
  sigfillset(&all);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attr, &all);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  if (::posix_spawn(&pid, argv[0], &actions, &attr, argv.data(), envp.data()) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  return pid;
}

// The line the fake estimator writes into `fifo` once it runs ("PID GRANDCHILD_PID"); empty when nothing
// came within 60 s.
std::string Announcement(const fs::path& fifo) {
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  if (fd < 0) return "";
  std::string text;
  while (text.find('\n') == std::string::npos) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 60000) != 1) break;
    char buf[64];
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n <= 0) break;  // (a FIFO's read end sees no hang-up before a writer has come and gone)
    text.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

bool Exists(pid_t pid) { return pid > 0 && fs::exists("/proc/" + std::to_string(pid)); }

TEST(InterruptCli, ASignalEndsTheEstimatorWhatItStartedAndTheTemporaryRecording) {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    SCOPED_TRACE(::strsignal(signal));
    TempDir tmp;
    const fs::path tmpdir = tmp.path() / "tmp", fifo = tmp.path() / "announce", run = tmp.path() / "run";
    fs::create_directories(tmpdir);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const pid_t vigil = StartVigil({"run", std::string(VIGIL_SOURCE_DIR) + "/configs/paper.yaml", "--set",
                                    "duration_s=2", "--set", "estimator.backend=external", "--set",
                                    "estimator.external.command=[" + std::string(VIGIL_FAKE_ESTIMATOR) +
                                        ", announce, \"{output}\", \"{recording}\"]",
                                    "-o", run.string()},
                                   {"TMPDIR=" + tmpdir.string(), "VIGIL_TEST_ANNOUNCE=" + fifo.string()},
                                   tmp.path() / "stderr.txt");
    ASSERT_GT(vigil, 0);
    std::istringstream announced(Announcement(fifo));
    pid_t estimator = 0, grandchild = 0;
    announced >> estimator >> grandchild;
    EXPECT_GT(estimator, 0) << "the estimator never announced itself";
    EXPECT_FALSE(fs::is_empty(tmpdir));  // the recording it reads is there while it runs

    ::kill(vigil, signal);
    int status = 0;
    ASSERT_EQ(::waitpid(vigil, &status, 0), vigil);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "status " << status;
    EXPECT_FALSE(Exists(estimator)) << "the estimator outlived vigil";
    EXPECT_FALSE(Exists(grandchild)) << "the estimator's child outlived vigil";
    EXPECT_TRUE(fs::is_empty(tmpdir)) << "a vigil-recording-* folder was left behind";
    EXPECT_FALSE(fs::exists(run));
    for (pid_t left : {estimator, grandchild})
      if (Exists(left)) ::kill(left, SIGKILL);
  }
}

}  // namespace
}  // namespace vigil
