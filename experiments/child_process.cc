#include "experiments/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "core/format.h"

extern char** environ;

namespace vigil::experiments {
namespace {

using Clock = std::chrono::steady_clock;

// posix_spawn's attributes and file actions, released whatever happens.
struct SpawnSetup {
  posix_spawnattr_t attr;
  posix_spawn_file_actions_t actions;
  SpawnSetup() {
    posix_spawnattr_init(&attr);
    posix_spawn_file_actions_init(&actions);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
  }
  SpawnSetup(const SpawnSetup&) = delete;
  SpawnSetup& operator=(const SpawnSetup&) = delete;
};

// Waits until `pid` has ended (left as a zombie, not reaped) or `deadline` passed; true when it ended.
// A pidfd gives a wait with a timeout; without one (old kernels), the child is polled.
bool WaitForExit(pid_t pid, Clock::time_point deadline) {
  const int pidfd = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
  if (pidfd >= 0) {
    bool ended = false;
    for (;;) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) break;
      pollfd fd{pidfd, POLLIN, 0};
      const int n = ::poll(&fd, 1, static_cast<int>(std::min<long long>(left, 1 << 30)));
      if (n > 0) {
        ended = true;
        break;
      }
      if (n < 0 && errno != EINTR) break;
    }
    ::close(pidfd);
    return ended;
  }
  while (Clock::now() < deadline) {
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
        info.si_pid == pid)
      return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

}  // namespace

std::string ChildProcessResult::Describe(double timeout_s) const {
  switch (outcome) {
    case Outcome::kExited:
      return "exit status " + std::to_string(exit_code);
    case Outcome::kSignaled:
      return "killed by signal " + std::to_string(signal) + " (" + ::strsignal(signal) + ")";
    case Outcome::kTimedOut:
      return "timed out after " + FormatDouble(timeout_s) + " s (process group killed)";
    case Outcome::kNotStarted:
      return "could not start: " + error;
  }
  return "?";
}

ChildProcessResult RunChildProcess(const ChildProcessOptions& options) {
  ChildProcessResult result;
  SpawnSetup setup;
  // A new process group (its id is the child's pid), default signal dispositions and an empty signal mask:
  // the child does not inherit what vigil blocks or ignores.
  sigset_t none, all;
  sigemptyset(&none);
  sigfillset(&all);
  posix_spawnattr_setpgroup(&setup.attr, 0);
  posix_spawnattr_setsigmask(&setup.attr, &none);
  posix_spawnattr_setsigdefault(&setup.attr, &all);
  posix_spawnattr_setflags(&setup.attr,
                           POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawn_file_actions_addopen(&setup.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&setup.actions, 1, options.stdout_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&setup.actions, 2, options.stderr_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!options.working_dir.empty())
    posix_spawn_file_actions_addchdir_np(&setup.actions, options.working_dir.c_str());

  std::vector<char*> argv;
  for (const std::string& arg : options.argv) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);

  const Clock::time_point start = Clock::now();
  pid_t pid = 0;
  const int rc =
      ::posix_spawn(&pid, options.program.c_str(), &setup.actions, &setup.attr, argv.data(), environ);
  if (rc != 0) {
    result.error = options.program + ": " + std::strerror(rc);
    return result;
  }
  const auto deadline =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout_s));
  const bool ended = WaitForExit(pid, deadline);
  // The child is a zombie or still running: its pid (= the group's id) cannot be reused yet, so the group
  // kill reaches only what it started.
  ::kill(-pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  if (!ended) {
    result.outcome = ChildProcessResult::Outcome::kTimedOut;
  } else if (WIFEXITED(status)) {
    result.outcome = ChildProcessResult::Outcome::kExited;
    result.exit_code = WEXITSTATUS(status);
  } else {
    result.outcome = ChildProcessResult::Outcome::kSignaled;
    result.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  }
  return result;
}

}  // namespace vigil::experiments
