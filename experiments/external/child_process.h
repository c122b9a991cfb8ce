// Runs a program as a child process without a shell: in a process group of its own, with its standard
// output and error going to files, its standard input from /dev/null, no other file of vigil's open, and a
// wall-clock timeout.
//
// Nothing the program starts outlives the call. Between vigil and the program sits a supervisor process, a
// subreaper (PR_SET_CHILD_SUBREAPER): whatever the program starts, even in a session of its own (setsid),
// becomes the supervisor's child when its parent ends. Once the program has ended (or timed out, or vigil
// was interrupted, or vigil died), the supervisor kills its process group and then every process left
// below it, waits for each, and only then reports the program's status.
//
// Interrupts: while an InterruptScope lives, SIGINT, SIGTERM and SIGHUP do not end vigil at once. The
// signal is handed on to every running program (its group, within 100 ms), which is given kInterruptGrace_s
// to end before it is killed; RunChildProcess then throws Interrupted, whose unwinding removes the caller's
// temporary and staged files, and vigil ends with the same signal (EndWithSignal, app/main.cc).
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace vigil::experiments {

struct ChildProcessOptions {
  std::string program;                             // path of the executable (not searched in PATH)
  std::vector<std::string> argv;                   // argv[0] included
  std::filesystem::path working_dir;               // empty: the caller's
  std::filesystem::path stdout_path, stderr_path;  // created or truncated
  double timeout_s = 60.0;
};

struct ChildProcessResult {
  enum class Outcome { kExited, kSignaled, kTimedOut, kNotStarted };
  Outcome outcome = Outcome::kNotStarted;
  int exit_code = -1;   // kExited
  int signal = 0;       // kSignaled
  std::string error;    // kNotStarted: why
  double wall_s = 0.0;  // from the spawn to the end of the wait

  bool succeeded() const { return outcome == Outcome::kExited && exit_code == 0; }
  // "exit status 3", "killed by signal 11 (Segmentation fault)", "timed out after 2 s (process group
  // killed)", "could not start: ...".
  std::string Describe(double timeout_s) const;
};

// How long an interrupted program may take to end after the signal was handed on to it.
inline constexpr double kInterruptGrace_s = 5.0;

// vigil received `signal` (SIGINT, SIGTERM or SIGHUP) while a program ran, or while an InterruptScope
// lived. Deliberately not a std::exception: nothing that records a failed run and goes on may catch it.
struct Interrupted {
  int signal = 0;
};

// Takes SIGINT, SIGTERM and SIGHUP for the scope's lifetime (nested and concurrent scopes share one
// handler; a signal that vigil ignored stays ignored). A signal that arrives while no program runs is
// recorded: ThrowIfInterrupted() throws it; a scope that ends with the signal unthrown ends vigil with it.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

// Throws Interrupted when an interrupt was recorded.
void ThrowIfInterrupted();

// Ends vigil as `signal` would have (default disposition, raised), so its exit status is the signal's.
[[noreturn]] void EndWithSignal(int signal);

// The timeout for poll(2) that waits `left`: whole milliseconds rounded up (at most 2^30), so that the wait
// never ends before the deadline (truncated, a timeout of 0.5 s fired up to 1 ms early).
int PollTimeoutMs(std::chrono::nanoseconds left);

// Starts `options.program` and waits for it and everything it started (see above). Never throws for what
// the child does; throws Interrupted (after the clean-up) when vigil was interrupted.
ChildProcessResult RunChildProcess(const ChildProcessOptions& options);

}  // namespace vigil::experiments
