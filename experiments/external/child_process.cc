#include "experiments/external/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

#include "core/format.h"

extern char** environ;

namespace vigil::experiments {
namespace {

using Clock = std::chrono::steady_clock;

// ---- Interrupts (async-signal-safe state) ----

constexpr int kInterruptSignals[] = {SIGINT, SIGTERM, SIGHUP};

std::atomic<int> g_interrupt{0};  // the signal received, 0 when none
std::atomic<int> g_scopes{0};     // InterruptScopes alive
std::once_flag g_handler_once;

// Records the signal; RunChildProcess hands it on to its program. Without a scope, vigil runs no program
// and the signal ends it as before.
extern "C" void OnInterrupt(int signal) {
  g_interrupt.store(signal);
  if (g_scopes.load() == 0) EndWithSignal(signal);
}

void InstallInterruptHandler() {
  std::call_once(g_handler_once, [] {
    for (int signal : kInterruptSignals) {
      struct sigaction old {};
      if (::sigaction(signal, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;  // e.g. nohup
      struct sigaction action {};
      action.sa_handler = OnInterrupt;
      sigemptyset(&action.sa_mask);
      action.sa_flags = SA_RESTART;
      ::sigaction(signal, &action, nullptr);
    }
  });
}

// ---- The supervisor (runs in a forked copy of a multi-threaded process: async-signal-safe calls only) ----

// What the supervisor reports on its pipe: first the start, then the program's wait status.
struct StartReport {
  pid_t pid = -1;  // the program's pid; -1 when it could not start
  int stage = 0;   // 0 ok; else where it failed (kStage*)
  int error = 0;   // errno
};
constexpr int kStageFork = 1, kStageStdin = 2, kStageStdout = 3, kStageStderr = 4, kStageChdir = 5,
              kStageExec = 6;

// Everything the forked processes need, prepared before fork().
struct SpawnPlan {
  const char* program;
  char* const* argv;
  const char* working_dir;  // null: unchanged
  const char* stdout_path;
  const char* stderr_path;
};

void WriteAll(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
}

bool ReadAll(int fd, void* data, std::size_t n) {
  char* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t k = ::read(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

void SetSignalsToDefault() {
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  for (int signal = 1; signal < NSIG; ++signal)
    if (signal != SIGKILL && signal != SIGSTOP) ::sigaction(signal, &action, nullptr);
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
}

// Closes every descriptor from `first` up, except `keep_a` and `keep_b`.
void CloseOtherDescriptors(int first, int keep_a, int keep_b) {
  const int low = std::min(keep_a, keep_b), high = std::max(keep_a, keep_b);
  const auto close_range = [](int from, int to) {
    if (from > to) return;
    if (::syscall(SYS_close_range, static_cast<unsigned>(from), static_cast<unsigned>(to), 0) == 0) return;
    for (int fd = from; fd <= std::min(to, 65535); ++fd) ::close(fd);
  };
  close_range(first, low - 1);
  close_range(low + 1, high - 1);
  close_range(high + 1, 0x7fffffff);
}

// In the program's process: its group, signals, descriptors and folder, then exec. Never returns.
[[noreturn]] void ExecProgram(const SpawnPlan& plan, int error_fd) {
  ::setpgid(0, 0);
  SetSignalsToDefault();
  const auto fail = [&](int stage) {
    const StartReport report{-1, stage, errno};
    WriteAll(error_fd, &report, sizeof report);
    ::_exit(127);
  };
  const auto open_as = [&](int target, const char* path, int flags, int stage) {
    const int fd = ::open(path, flags, 0644);
    if (fd < 0) fail(stage);
    if (fd == target) return;
    if (::dup2(fd, target) < 0) fail(stage);
    ::close(fd);
  };
  open_as(0, "/dev/null", O_RDONLY, kStageStdin);
  open_as(1, plan.stdout_path, O_WRONLY | O_CREAT | O_TRUNC, kStageStdout);
  open_as(2, plan.stderr_path, O_WRONLY | O_CREAT | O_TRUNC, kStageStderr);
  if (plan.working_dir != nullptr && ::chdir(plan.working_dir) != 0) fail(kStageChdir);
  ::execve(plan.program, plan.argv, environ);
  fail(kStageExec);
  ::_exit(127);  // not reached: fail() exits
}

// Appends the decimal digits of `value` to `path` at `*at`.
void AppendNumber(char* path, std::size_t* at, long value) {
  char digits[24];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + value % 10);
    value /= 10;
  } while (value > 0);
  while (n > 0) path[(*at)++] = digits[--n];
}

// Reads at most `size` bytes of the file `path`; -1 when it cannot be opened.
ssize_t ReadSmallFile(const char* path, char* text, std::size_t size) {
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return -1;
  std::size_t got = 0;
  while (got < size) {
    const ssize_t k = ::read(fd, text + got, size - got);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;
    got += static_cast<std::size_t>(k);
  }
  ::close(fd);
  return static_cast<ssize_t>(got);
}

// Without /proc/self/task/<pid>/children (a kernel without CONFIG_PROC_CHILDREN): every /proc/<pid>/stat
// whose parent (the field after the state) is `self`.
int ScanChildren(pid_t self, pid_t* children, int max) {
  const int dir = ::open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return 0;
  int count = 0;
  alignas(8) char entries[4096];
  for (long n; count < max && (n = ::syscall(SYS_getdents64, dir, entries, sizeof entries)) > 0;) {
    for (long at = 0; at < n && count < max;) {
      const char* name = entries + at + 19;  // struct linux_dirent64: ino 8, off 8, reclen 2, type 1, name
      unsigned short reclen = 0;
      std::memcpy(&reclen, entries + at + 16, sizeof reclen);
      at += reclen;
      long pid = 0;
      for (const char* c = name; *c != '\0'; ++c) pid = *c >= '0' && *c <= '9' ? pid * 10 + (*c - '0') : -1;
      if (pid <= 0) continue;
      char path[64] = "/proc/";
      std::size_t end = 6;
      AppendNumber(path, &end, pid);
      std::memcpy(path + end, "/stat", 6);
      char stat[512];
      const ssize_t size = ReadSmallFile(path, stat, sizeof stat - 1);
      if (size <= 0) continue;
      stat[size] = '\0';
      const char* paren = std::strrchr(stat, ')');  // the command name may hold anything, ')' included
      if (paren == nullptr || paren[1] == '\0' || paren[2] == '\0') continue;
      long parent = 0;
      for (const char* c = paren + 4; *c >= '0' && *c <= '9'; ++c) parent = parent * 10 + (*c - '0');
      if (parent == self) children[count++] = static_cast<pid_t>(pid);
    }
  }
  ::close(dir);
  return count;
}

// The supervisor's children, from /proc/self/task/<pid>/children (it is single-threaded): at most `max`.
int ReadChildren(pid_t* children, int max) {
  char path[64] = "/proc/self/task/";
  std::size_t at = std::strlen(path);
  AppendNumber(path, &at, ::getpid());
  std::memcpy(path + at, "/children", 10);
  char text[4096];
  const ssize_t size = ReadSmallFile(path, text, sizeof text);
  if (size < 0) return ScanChildren(::getpid(), children, max);
  int count = 0;
  long value = 0;
  bool in_number = false;
  for (ssize_t i = 0; i < size && count < max; ++i) {
    if (text[i] >= '0' && text[i] <= '9') {
      value = value * 10 + (text[i] - '0');
      in_number = true;
    } else if (in_number) {
      children[count++] = static_cast<pid_t>(value);
      value = 0;
      in_number = false;
    }
  }
  return count;
}

// Kills the program's group and every process left below the supervisor, and reaps them all.
void KillDescendants(pid_t program) {
  for (;;) {
    ::kill(-program, SIGKILL);
    pid_t children[256];
    const int n = ReadChildren(children, 256);
    for (int i = 0; i < n; ++i) ::kill(children[i], SIGKILL);
    int status = 0;
    const pid_t reaped = ::waitpid(-1, &status, WNOHANG);
    if (reaped < 0 && errno == ECHILD) return;
    if (reaped == 0) {  // a child is still dying (or was not listed yet): look again shortly
      const timespec pause{0, 1000000};
      ::nanosleep(&pause, nullptr);
    }
  }
}

// The supervisor: starts the program, hands it the commands read from `command_fd` (a signal number; end
// of file: vigil is gone, so SIGKILL), waits for it, then kills what is left and reports. Never returns.
[[noreturn]] void Supervise(const SpawnPlan& plan, int report_fd, int command_fd) {
  ::setpgid(0, 0);  // out of vigil's group: a Ctrl-C at the terminal reaches vigil, which hands it on
  SetSignalsToDefault();
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) ::sigaction(signal, &ignore, nullptr);
  CloseOtherDescriptors(3, report_fd, command_fd);
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);
  int exec_pipe[2];
  if (::pipe2(exec_pipe, O_CLOEXEC) != 0) {
    const StartReport report{-1, kStageFork, errno};
    WriteAll(report_fd, &report, sizeof report);
    ::_exit(0);
  }
  const pid_t program = ::fork();
  if (program == 0) {
    ::close(exec_pipe[0]);
    ExecProgram(plan, exec_pipe[1]);
  }
  ::close(exec_pipe[1]);
  StartReport report{program, 0, errno};
  if (program < 0) {
    report.stage = kStageFork;
    WriteAll(report_fd, &report, sizeof report);
    ::_exit(0);
  }
  ::setpgid(program, program);  // also here, so that a signal never finds the group missing
  StartReport failed;
  if (ReadAll(exec_pipe[0], &failed, sizeof failed)) report = {-1, failed.stage, failed.error};
  ::close(exec_pipe[0]);
  WriteAll(report_fd, &report, sizeof report);

  const int pidfd = static_cast<int>(::syscall(SYS_pidfd_open, program, 0));
  int status = 0;
  bool ended = false;
  while (!ended) {
    pollfd fds[2] = {{pidfd, POLLIN, 0}, {command_fd, POLLIN, 0}};
    ::poll(fds, 2, pidfd >= 0 ? -1 : 5);  // without a pidfd (old kernels), the program is polled
    if (command_fd >= 0 && (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
      unsigned char command = 0;
      const ssize_t k = ::read(command_fd, &command, 1);
      if (k < 0 && errno == EINTR) continue;
      const int signal = k == 1 ? command : SIGKILL;
      if (k != 1) command_fd = -1;  // vigil is gone: nothing more will come
      ::kill(-program, signal);
      ::kill(program, signal);
    }
    int reaped_status = 0;
    for (pid_t reaped; (reaped = ::waitpid(-1, &reaped_status, WNOHANG)) > 0;) {
      if (reaped != program) continue;  // an orphan the program left, adopted and reaped
      status = reaped_status;
      ended = true;
    }
  }
  KillDescendants(program);
  WriteAll(report_fd, &status, sizeof status);
  ::_exit(0);
}

std::string StartError(const StartReport& report, const ChildProcessOptions& options) {
  const std::string why = std::strerror(report.error);
  switch (report.stage) {
    case kStageStdout:
      return options.stdout_path.string() + ": " + why;
    case kStageStderr:
      return options.stderr_path.string() + ": " + why;
    case kStageStdin:
      return "/dev/null: " + why;
    case kStageChdir:
      return options.working_dir.string() + ": " + why;
    case kStageFork:
      return "fork: " + why;
    default:
      return options.program + ": " + why;
  }
}

}  // namespace

InterruptScope::InterruptScope() {
  InstallInterruptHandler();
  ++g_scopes;
}

InterruptScope::~InterruptScope() {
  if (--g_scopes == 0 && g_interrupt.load() != 0 && std::uncaught_exceptions() == 0)
    EndWithSignal(g_interrupt.load());  // the signal came after the last check: end as it asked
}

void ThrowIfInterrupted() {
  if (const int signal = g_interrupt.load(); signal != 0) throw Interrupted{signal};
}

void EndWithSignal(int signal) {
  ::signal(signal, SIG_DFL);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, signal);
  ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  ::raise(signal);
  ::_exit(128 + signal);
}

int PollTimeoutMs(std::chrono::nanoseconds left) {
  if (left <= std::chrono::nanoseconds::zero()) return 0;
  return static_cast<int>(
      std::min<long long>(std::chrono::ceil<std::chrono::milliseconds>(left).count(), 1 << 30));
}

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
  const InterruptScope scope;
  ThrowIfInterrupted();
  ChildProcessResult result;
  std::vector<char*> argv;
  for (const std::string& arg : options.argv) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  const std::string working_dir = options.working_dir.string();
  const SpawnPlan plan{options.program.c_str(), argv.data(),
                       working_dir.empty() ? nullptr : working_dir.c_str(), options.stdout_path.c_str(),
                       options.stderr_path.c_str()};
  int report[2], command[2];
  if (::pipe2(report, O_CLOEXEC) != 0) {
    result.error = std::string("pipe: ") + std::strerror(errno);
    return result;
  }
  if (::pipe2(command, O_CLOEXEC) != 0) {
    result.error = std::string("pipe: ") + std::strerror(errno);
    ::close(report[0]);
    ::close(report[1]);
    return result;
  }
  const Clock::time_point start = Clock::now();
  const pid_t supervisor = ::fork();
  if (supervisor == 0) Supervise(plan, report[1], command[0]);
  ::close(report[1]);
  ::close(command[0]);
  StartReport started;
  if (supervisor < 0 || !ReadAll(report[0], &started, sizeof started)) {
    started = {-1, kStageFork, supervisor < 0 ? errno : EPIPE};
  }
  bool timed_out = false;
  int status = 0;
  bool reported = false;
  if (started.pid > 0) {
    // Wait for the final report. An interrupt is handed on to the program, which gets kInterruptGrace_s to
    // end; at the deadline the supervisor is told to kill it, and the report follows.
    Clock::time_point deadline =
        start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeout_s));
    bool grace_set = false;
    for (;;) {
      if (const int signal = g_interrupt.load(); !grace_set && signal != 0) {
        grace_set = true;
        const unsigned char forward = static_cast<unsigned char>(signal);
        WriteAll(command[1], &forward, 1);
        deadline = std::min(deadline, Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                         std::chrono::duration<double>(kInterruptGrace_s)));
      }
      const Clock::duration left = deadline - Clock::now();
      if (left <= Clock::duration::zero()) {
        timed_out = !grace_set;
        const unsigned char kill_command = SIGKILL;
        WriteAll(command[1], &kill_command, 1);
        break;
      }
      pollfd fd{report[0], POLLIN, 0};
      // In slices of 100 ms, so that an interrupt (received on any thread) is handed on soon.
      const int n = ::poll(&fd, 1, std::min(PollTimeoutMs(left), 100));
      if (n > 0) break;
    }
    reported = ReadAll(report[0], &status, sizeof status);
  }
  ::close(command[1]);
  ::close(report[0]);
  if (supervisor > 0)
    while (::waitpid(supervisor, nullptr, 0) < 0 && errno == EINTR) {
    }
  result.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  ThrowIfInterrupted();
  if (started.pid <= 0) {
    result.error = StartError(started, options);
  } else if (timed_out) {
    result.outcome = ChildProcessResult::Outcome::kTimedOut;
  } else if (!reported) {
    result.outcome = ChildProcessResult::Outcome::kSignaled;  // the supervisor itself died
    result.signal = SIGKILL;
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
